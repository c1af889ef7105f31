#include "SceneAssembly.h"

#include <cmath>
#include <string>
#include <utility>

#include "GltfCameras.h"
#include "GltfMaterials.h"
#include "tofsim/scene/SceneBound.h"
#include "tofsim/util/Error.h"

namespace tofsim::scene::detail {

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

std::string nodeKey(int node) { return "node[" + std::to_string(node) + "]"; }
}  // namespace

SceneCamera placeCamera(const GltfDocument& doc, const CameraSlot& slot, int node,
                        const glm::dmat4& world) {
  const CameraDesc& camera = doc.cameras[slot.camera];
  SceneCamera out = convertCamera(camera, NodeInstance{node, -1, world});
  const glm::dvec3 position(world[3]);
  if (!withinSceneBound(position)) {
    throw InputError(FileLoc{doc.file}, nodeKey(node),
                     "camera '" + camera.name + "' lies " + sceneBoundText(position));
  }
  if (!usable(out)) {
    throw InputError(FileLoc{doc.file}, nodeKey(node),
                     "camera '" + camera.name +
                         "' has a degenerate transform, or a yfov "
                         "outside (0, 180) degrees or a negative aspectRatio");
  }
  return out;
}

Mesh rebakeMesh(const GltfDocument& doc, const MeshSlot& slot, const Mesh& rest,
                const glm::dmat4& world) {
  Mesh mesh;
  mesh.name = rest.name;
  mesh.node = rest.node;
  mesh.material = rest.material;
  LoadReport unused;  // the counts are the rest pose's, reported once
  buildPrimitive(doc, slot.primitive, world, mesh, unused);
  return mesh;
}

SceneAssembly assembleScene(const GltfDocument& doc, LoadReport& report,
                            const std::vector<bool>& keepEmpty) {
  SceneAssembly out;
  Scene& scene = out.scene;
  convertMaterials(doc, scene, report);
  int defaultIndex = -1;
  out.instances = flattenNodes(doc);

  for (std::size_t i = 0; i < out.instances.size(); ++i) {
    const NodeInstance& instance = out.instances[i];
    const Node& node = doc.nodes[instance.node];
    if (node.camera >= 0) {
      if (node.camera >= static_cast<int>(doc.cameras.size())) {
        throw InputError(FileLoc{doc.file}, nodeKey(instance.node),
                         "camera " + std::to_string(node.camera) + " does not exist");
      }
      if (doc.cameras[node.camera].perspective) {
        const CameraSlot slot{i, node.camera};
        scene.cameras.push_back(placeCamera(doc, slot, instance.node, instance.world));
        out.cameraSlots.push_back(slot);
      } else {
        ++report.orthographicCameras;
      }
    }
    if (node.mesh < 0) continue;
    if (node.mesh >= static_cast<int>(doc.meshes.size())) {
      throw InputError(FileLoc{doc.file}, nodeKey(instance.node),
                       "mesh " + std::to_string(node.mesh) + " does not exist");
    }
    const MeshDesc& meshDesc = doc.meshes[node.mesh];
    for (std::size_t p = 0; p < meshDesc.primitives.size(); ++p) {
      const int material = meshDesc.primitives[p].material;
      if (material >= static_cast<int>(doc.materials.size())) {
        throw InputError(FileLoc{doc.file}, "mesh[" + std::to_string(node.mesh) + "]",
                         "material " + std::to_string(material) + " does not exist");
      }
      const PrimitiveRef ref{node.mesh, static_cast<int>(p),
                             material >= 0 ? doc.materials[material].baseColorTexCoord : 0};
      Mesh mesh;
      mesh.name = meshDesc.name.empty() ? "mesh_" + std::to_string(node.mesh) : meshDesc.name;
      if (meshDesc.primitives.size() > 1) mesh.name += "/" + std::to_string(p);
      mesh.node = node.name;
      const bool keep = i < keepEmpty.size() && keepEmpty[i];
      if (!buildPrimitive(doc, ref, instance.world, mesh, report)) continue;
      if (mesh.indices.empty() && !keep) {
        for (const std::string* n : {&mesh.node, &mesh.name}) {
          if (!n->empty()) scene.arealess.push_back(*n);
        }
        continue;
      }
      if (material >= 0) {
        mesh.material = material;
      } else {
        if (defaultIndex < 0) {
          scene.materials.push_back(defaultMaterial());
          defaultIndex = static_cast<int>(scene.materials.size() - 1);
        }
        mesh.material = defaultIndex;
      }
      scene.meshes.push_back(std::move(mesh));
      out.meshSlots.push_back({i, ref});
    }
  }
  return out;
}

}  // namespace tofsim::scene::detail
