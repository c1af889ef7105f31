#include "tofsim/pipeline/SceneInfo.h"

#include <cstdio>
#include <string>
#include <vector>

#include "tofsim/physics/GltfBrdf.h"
#include "tofsim/scene/AnimatedScene.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::pipeline {

namespace {

std::string format(const char* fmt, auto... args) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, fmt, args...);
  return buffer;
}

// What render.materials: lambertian makes of a material: albedo / pi, the
// glTF metallic-roughness values unread.
std::string lambertianKind(const scene::Material& m) {
  const bool dropsGltf = m.metallic > 0.0f || m.roughness < 1.0f || m.metallicRoughnessTexture >= 0;
  return dropsGltf ? "albedo / pi (metallic, roughness ignored)" : "albedo / pi";
}

// What render.materials: gltf makes of it (shaders/gltf_brdf.glsl).
std::string gltfKind(const scene::Material& m) {
  const bool textured = m.metallicRoughnessTexture >= 0;
  const char* kind = textured             ? "metallic-roughness texture x factors"
                     : m.metallic <= 0.0f ? "dielectric: (1 - F) albedo / pi + F GGX, F0 0.04"
                     : m.metallic >= 1.0f ? "metal: F(albedo) GGX"
                                          : "dielectric / metal mix by metallic";
  return format("%s; metallic %.3g, roughness %.3g%s", kind, m.metallic, m.roughness,
                textured                                   ? " (x texture B, G)"
                : m.roughness < physics::kGltfMinRoughness ? " (clamped to 0.001)"
                                                           : "");
}

std::string joined(const std::vector<std::string>& parts) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : ", ") + p;
  return out;
}

std::string reportText(const scene::LoadReport& r) {
  std::string out = "loader:\n";
  const auto count = [&](const char* what, std::size_t n) {
    if (n > 0) out += format("  %zu %s\n", n, what);
  };
  count("point/line primitive(s) skipped", r.skippedPrimitives);
  count("zero-area triangle(s) dropped", r.degenerateTriangles);
  count("primitive(s) without normals (flat normals made)", r.flatNormalPrimitives);
  count("metallic material(s) (diffuse base colour unless render.materials: gltf)",
        r.metallicMaterials);
  count("emissive material(s) (emission ignored)", r.emissiveMaterials);
  count("transmissive material(s) (rendered as diffuse base colour)", r.transmissiveMaterials);
  count("orthographic camera(s) skipped", r.orthographicCameras);
  count("skin(s) ignored (skinned meshes placed rigidly by their nodes)", r.skins);
  count("mesh(es) with morph targets (targets and weights ignored)", r.morphTargetMeshes);
  for (const std::string& w : r.warnings) out += "  warning: " + w + "\n";
  if (out == "loader:\n") out += "  nothing skipped or changed\n";
  return out;
}

std::string nodeLabel(const scene::AnimationChannel& c) {
  return format("node[%d]", c.node) + (c.nodeName.empty() ? "" : " '" + c.nodeName + "'");
}

// What the animations play (every one at once, on one clock) and ignore.
std::string animationText(const scene::AnimatedScene& animated) {
  const std::vector<scene::Animation>& animations = animated.animations();
  std::string out = format("animations: %zu", animations.size());
  if (animations.empty()) return out + "\n";
  out += format(" (played together, %.4g .. %.4g s; moving: %zu mesh(es), %zu camera(s))\n",
                animated.start_s(), animated.end_s(), animated.movingMeshes().size(),
                animated.movingCameras().size());
  for (std::size_t i = 0; i < animations.size(); ++i) {
    const scene::Animation& a = animations[i];
    const char* name = a.name.empty() ? "(unnamed)" : a.name.c_str();
    out += a.channels.empty()
               ? format("  [%zu] %-24s no channel played\n", i, name)
               : format("  [%zu] %-24s %.4g .. %.4g s (duration %.4g s), %zu channel(s)\n", i, name,
                        a.start_s(), a.end_s(), a.duration_s(), a.channels.size());
    for (const scene::AnimationChannel& c : a.channels) {
      out +=
          format("        %-20s %-11s %-11s %zu keyframes\n", nodeLabel(c).c_str(),
                 scene::toString(c.property), scene::toString(c.interpolation), c.keyframeCount());
    }
    if (a.ignoredWeightChannels > 0) {
      out +=
          format("        ignored: %zu morph-target weights channel(s)\n", a.ignoredWeightChannels);
    }
    if (a.ignoredOtherChannels > 0) {
      out += format("        ignored: %zu channel(s) without a node or of another path\n",
                    a.ignoredOtherChannels);
    }
  }
  return out;
}

}  // namespace

std::string describeScene(const std::filesystem::path& sceneFile) {
  scene::LoadReport report;
  const scene::AnimatedScene animated = scene::AnimatedScene::load(sceneFile, &report);
  const scene::Scene& s = animated.restScene();
  std::string out = sceneFile.string() + "\n";
  out += format("meshes: %zu, triangles: %zu\n", s.meshes.size(), s.triangleCount());
  for (std::size_t i = 0; i < s.meshes.size(); ++i) {
    const scene::Mesh& m = s.meshes[i];
    const std::string material =
        m.material >= 0 && m.material < static_cast<int>(s.materials.size())
            ? s.materials[m.material].name
            : "?";
    out += format("  [%zu] %-24s %8zu triangles  material %s%s\n", i, m.name.c_str(),
                  m.triangleCount(), material.c_str(), m.uvs.empty() ? "" : "  (uv)");
  }
  const scene::Bounds b = s.bounds();
  const glm::vec3 size = b.max - b.min;
  out += format(
      "bounds (m): min [%.4g, %.4g, %.4g]  max [%.4g, %.4g, %.4g]  size [%.4g, %.4g, %.4g]\n",
      b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z, size.x, size.y, size.z);
  out += format("materials: %zu (as each render.materials mode renders it)\n", s.materials.size());
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    const scene::Material& m = s.materials[i];
    out += format("  [%zu] %-24s albedo [%.3f, %.3f, %.3f]%s\n", i, m.name.c_str(), m.albedo.x,
                  m.albedo.y, m.albedo.z, m.albedoTexture >= 0 ? " x texture" : "");
    out += "        lambertian: " + lambertianKind(m) + "\n";
    out += "        gltf:       " + gltfKind(m) + "\n";
    if (i < report.ignoredMaterialParts.size() && !report.ignoredMaterialParts[i].empty()) {
      out += "        ignored:    " + joined(report.ignoredMaterialParts[i]) + "\n";
    }
  }
  out += format("textures: %zu\n", s.textures.size());
  out += format("cameras: %zu\n", s.cameras.size());
  for (std::size_t i = 0; i < s.cameras.size(); ++i) {
    const scene::SceneCamera& c = s.cameras[i];
    out += format(
        "  [%zu] %-24s position [%.4g, %.4g, %.4g] m  forward [%.3f, %.3f, %.3f]  fov_y %.4g deg\n",
        i, c.name.c_str(), c.position_world.x, c.position_world.y, c.position_world.z,
        c.forward_world.x, c.forward_world.y, c.forward_world.z, c.fov_y_deg);
  }
  out += animationText(animated);
  return out + reportText(report);
}

}  // namespace tofsim::pipeline
