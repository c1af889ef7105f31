#include "LitBounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tofsim::cpu {

LitBounds::LitBounds(const scene::Scene& scene) {
  const scene::Bounds all = scene.bounds();
  epsilon_m_ = 1e-4f * std::max(glm::length(all.max - all.min), 1e-6f);
  for (const scene::Mesh& m : scene.meshes) {
    if (m.positions_world.empty()) continue;
    MeshBox b;
    b.box = {m.positions_world.front(), m.positions_world.front()};
    for (const glm::vec3& p : m.positions_world) {
      b.box.min = glm::min(b.box.min, p);
      b.box.max = glm::max(b.box.max, p);
    }
    glm::vec3 areaNormal(0.0f);
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      const glm::vec3 a = m.positions_world[m.indices[t]];
      areaNormal += glm::cross(m.positions_world[m.indices[t + 1]] - a,
                               m.positions_world[m.indices[t + 2]] - a);
    }
    if (glm::length(areaNormal) > 0.0f) {
      b.normal = glm::normalize(areaNormal);
      b.offset = glm::dot(b.normal, m.positions_world.front());
      b.planar =
          std::all_of(m.positions_world.begin(), m.positions_world.end(), [&](const glm::vec3& p) {
            return std::fabs(glm::dot(b.normal, p) - b.offset) <= epsilon_m_;
          });
    }
    meshes_.push_back(b);
  }
}

std::optional<scene::Bounds> LitBounds::of(const capture::Light& light) const {
  if (light.type != capture::Light::Type::Lambertian) return std::nullopt;
  const glm::vec3 axis = glm::normalize(light.direction_world);
  std::optional<scene::Bounds> lit;
  bool skipped = false;
  for (const MeshBox& m : meshes_) {
    // The light's own plane: it emits into the half space in front of it, so
    // no ray of it meets the plane again.
    if (m.planar && std::fabs(glm::dot(m.normal, axis)) > 0.9999f &&
        std::fabs(glm::dot(m.normal, light.position_world) - m.offset) <= epsilon_m_) {
      skipped = true;
      continue;
    }
    if (!lit) {
      lit = m.box;
    } else {
      lit->min = glm::min(lit->min, m.box.min);
      lit->max = glm::max(lit->max, m.box.max);
    }
  }
  if (!skipped) return std::nullopt;
  // Nothing else in the scene: an empty box meets no ray.
  if (!lit) {
    const float inf = std::numeric_limits<float>::infinity();
    return scene::Bounds{glm::vec3(inf), glm::vec3(-inf)};
  }
  // A margin for the rounding of the hit point against the box's faces.
  lit->min -= glm::vec3(epsilon_m_);
  lit->max += glm::vec3(epsilon_m_);
  return lit;
}

bool rayMeetsBox(const glm::vec3& origin, const glm::vec3& direction, const scene::Bounds& box) {
  float tNear = 0.0f, tFar = std::numeric_limits<float>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (direction[a] == 0.0f) {
      if (origin[a] < box.min[a] || origin[a] > box.max[a]) return false;
      continue;
    }
    const float inv = 1.0f / direction[a];
    float t0 = (box.min[a] - origin[a]) * inv, t1 = (box.max[a] - origin[a]) * inv;
    if (t0 > t1) std::swap(t0, t1);
    tNear = std::max(tNear, t0);
    tFar = std::min(tFar, t1);
    if (tNear > tFar) return false;
  }
  return true;
}

}  // namespace tofsim::cpu
