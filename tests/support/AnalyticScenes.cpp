#include "AnalyticScenes.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace tofsim::test {

void addQuad(scene::Scene& scene, const glm::vec3& center, const glm::vec3& normal, float size_m,
             const glm::vec3& albedo) {
  const glm::vec3 n = glm::normalize(normal);
  const glm::vec3 helper = std::abs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 u = glm::normalize(glm::cross(helper, n)) * (0.5f * size_m);
  const glm::vec3 v = glm::cross(n, glm::normalize(u)) * (0.5f * size_m);
  scene::Material material;
  material.name = "quad" + std::to_string(scene.materials.size());
  material.albedo = albedo;
  scene.materials.push_back(material);
  scene::Mesh mesh;
  mesh.name = material.name;
  mesh.positions_world = {center - u - v, center + u - v, center + u + v, center - u + v};
  mesh.normals_world.assign(4, n);
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.material = static_cast<int32_t>(scene.materials.size() - 1);
  scene.meshes.push_back(mesh);
}

void addBox(scene::Scene& scene, const std::string& name, glm::vec3 lo, glm::vec3 hi,
            bool inwards) {
  scene::Mesh m;
  m.name = name;
  for (int i = 0; i < 8; ++i) {
    m.positions_world.emplace_back(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    m.normals_world.emplace_back(0.0f, 0.0f, 1.0f);
  }
  const glm::vec3 centre = 0.5f * (lo + hi);
  // Each face's 4 corners in order around it.
  const int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    for (const auto& t : {std::array<int, 3>{f[0], f[1], f[2]}, std::array<int, 3>{f[0], f[2], f[3]}}) {
      const glm::vec3 a = m.positions_world[t[0]], b = m.positions_world[t[1]],
                      c = m.positions_world[t[2]];
      const bool out = glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0f - centre) > 0.0f;
      const bool flip = out == inwards;
      m.indices.insert(m.indices.end(), {static_cast<uint32_t>(t[0]),
                                         static_cast<uint32_t>(flip ? t[2] : t[1]),
                                         static_cast<uint32_t>(flip ? t[1] : t[2])});
    }
  }
  scene.meshes.push_back(std::move(m));
}

scene::Scene makePlane(float size_m, const glm::vec3& albedo) {
  scene::Scene scene;
  addQuad(scene, glm::vec3(0.0f), glm::vec3(0, 0, 1), size_m, albedo);
  return scene;
}

}  // namespace tofsim::test

namespace tofsim::test {

scene::Scene makeCorner(const glm::vec3& floorAlbedo, const glm::vec3& wallAlbedo) {
  scene::Scene scene;
  addQuad(scene, glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0, 1, 0), 2.0f, floorAlbedo);
  addQuad(scene, glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0, 0, 1), 2.0f, wallAlbedo);
  return scene;
}

scene::Scene makeClosedBox(float side_m, const glm::vec3& albedo) {
  scene::Scene scene;
  const float h = 0.5f * side_m;
  for (int axis = 0; axis < 3; ++axis) {
    for (const float sign : {-1.0f, 1.0f}) {
      glm::vec3 centre(0.0f);
      centre[axis] = sign * h;
      addQuad(scene, centre, -centre / h, side_m, albedo);
    }
  }
  return scene;
}

}  // namespace tofsim::test
