#include "tofsim/scene/GltfLoader.h"

#include <cmath>
#include <string>

#include "GltfCameras.h"
#include "GltfMaterials.h"
#include "NodeTransforms.h"
#include "PrimitiveBuilder.h"
#include "RequiredExtensions.h"
#include "TinyGltfImport.h"
#include "tofsim/util/Error.h"

namespace tofsim::scene {

namespace {
// A camera the renderer can use: finite pose, an orthonormal-able frame and
// a field of view in (0, 180) degrees (aspect 0 means "from the image").
bool usable(const SceneCamera& c) {
  const auto finite = [](const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  return finite(c.position_world) && finite(c.forward_world) && finite(c.up_world) &&
         c.fov_y_deg > 0.0f && c.fov_y_deg < 180.0f && std::isfinite(c.aspect) && c.aspect >= 0.0f;
}
}  // namespace

Scene loadGltf(const std::filesystem::path& path, LoadReport* reportOut) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(FileLoc{path.string()}, "", "glTF file not found");
  }
  detail::checkRequiredExtensions(path);
  const detail::GltfDocument doc = detail::importGltf(path);

  LoadReport report;
  report.warnings = doc.warnings;
  Scene scene;
  detail::convertMaterials(doc, scene, report);
  int defaultMaterial = -1;

  for (const detail::NodeInstance& instance : detail::flattenNodes(doc)) {
    const detail::Node& node = doc.nodes[instance.node];
    if (node.camera >= 0) {
      if (node.camera >= static_cast<int>(doc.cameras.size())) {
        throw InputError(FileLoc{doc.file}, "node[" + std::to_string(instance.node) + "]",
                         "camera " + std::to_string(node.camera) + " does not exist");
      }
      const detail::CameraDesc& camera = doc.cameras[node.camera];
      if (camera.perspective) {
        scene.cameras.push_back(detail::convertCamera(camera, instance));
        if (!usable(scene.cameras.back())) {
          throw InputError(FileLoc{doc.file}, "node[" + std::to_string(instance.node) + "]",
                           "camera '" + camera.name +
                               "' has a degenerate transform, or a yfov "
                               "outside (0, 180) degrees or a negative aspectRatio");
        }
      } else {
        ++report.orthographicCameras;
      }
    }
    if (node.mesh < 0) continue;
    if (node.mesh >= static_cast<int>(doc.meshes.size())) {
      throw InputError(FileLoc{doc.file}, "node[" + std::to_string(instance.node) + "]",
                       "mesh " + std::to_string(node.mesh) + " does not exist");
    }
    const detail::MeshDesc& meshDesc = doc.meshes[node.mesh];
    for (std::size_t p = 0; p < meshDesc.primitives.size(); ++p) {
      const int material = meshDesc.primitives[p].material;
      if (material >= static_cast<int>(doc.materials.size())) {
        throw InputError(FileLoc{doc.file}, "mesh[" + std::to_string(node.mesh) + "]",
                         "material " + std::to_string(material) + " does not exist");
      }
      const detail::PrimitiveRef ref{node.mesh, static_cast<int>(p),
                                     material >= 0 ? doc.materials[material].baseColorTexCoord : 0};
      Mesh mesh;
      mesh.name = meshDesc.name.empty() ? "mesh_" + std::to_string(node.mesh) : meshDesc.name;
      if (meshDesc.primitives.size() > 1) mesh.name += "/" + std::to_string(p);
      mesh.node = node.name;
      if (!detail::buildPrimitive(doc, ref, instance.world, mesh, report) || mesh.indices.empty()) {
        continue;
      }
      if (material >= 0) {
        mesh.material = material;
      } else {
        if (defaultMaterial < 0) {
          scene.materials.push_back(detail::defaultMaterial());
          defaultMaterial = static_cast<int>(scene.materials.size() - 1);
        }
        mesh.material = defaultMaterial;
      }
      scene.meshes.push_back(std::move(mesh));
    }
  }
  if (reportOut) *reportOut = std::move(report);
  return scene;
}

}  // namespace tofsim::scene
