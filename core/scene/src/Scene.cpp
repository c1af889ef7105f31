#include "tofsim/scene/Scene.h"

#include <limits>

namespace tofsim::scene {

std::size_t Scene::triangleCount() const {
  std::size_t n = 0;
  for (const Mesh& m : meshes) n += m.triangleCount();
  return n;
}

Bounds Scene::bounds() const {
  Bounds b{glm::vec3(std::numeric_limits<float>::max()),
           glm::vec3(std::numeric_limits<float>::lowest())};
  bool any = false;
  for (const Mesh& m : meshes) {
    for (const uint32_t i : m.indices) {
      b.min = glm::min(b.min, m.positions_world[i]);
      b.max = glm::max(b.max, m.positions_world[i]);
      any = true;
    }
  }
  return any ? b : Bounds{};
}

}  // namespace tofsim::scene
