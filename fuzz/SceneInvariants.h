#pragma once
// What the renderer relies on of every scene loadGltf returns: indices in
// range, finite positions and cameras, all within the scene bound
// (SceneBound.h: past it the tracers fail). fuzz_gltf traps when a loaded scene
// breaks it; tests/hardening/FuzzRegressionTest checks its saved inputs with
// the same function.

#include <cmath>

#include "tofsim/scene/Scene.h"
#include "tofsim/scene/SceneBound.h"

namespace tofsim::fuzz {

inline bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline bool inBound(const glm::vec3& v) { return scene::withinSceneBound(glm::dvec3(v)); }

inline bool renderable(const scene::Scene& scene) {
  for (const scene::SceneCamera& c : scene.cameras) {
    if (!std::isfinite(c.fov_y_deg) || !finite(c.position_world) || !finite(c.forward_world) ||
        !finite(c.up_world) || !inBound(c.position_world)) {
      return false;
    }
  }
  for (const scene::Mesh& mesh : scene.meshes) {
    for (const uint32_t i : mesh.indices) {
      if (i >= mesh.positions_world.size()) return false;
    }
    for (const glm::vec3& p : mesh.positions_world) {
      if (!finite(p) || !inBound(p)) return false;
    }
  }
  return true;
}

}  // namespace tofsim::fuzz
