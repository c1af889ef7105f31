#include "RsmVpls.h"

#include <cmath>
#include <optional>

#include "ParallelFor.h"

namespace tofsim::cpu {

namespace {

// One RSM view: the basis of glm::lookAt(l, l + forward, up) and its half angle.
struct RsmView {
  glm::vec3 forward, right, up;
  float halfAngle_rad;
};

RsmView lookAtView(const glm::vec3& forward, const glm::vec3& up, float half) {
  const glm::vec3 f = glm::normalize(forward);
  const glm::vec3 s = glm::normalize(glm::cross(f, up));
  return {f, s, glm::cross(s, f), half};
}

// The views of Vpls.cpp's rsmViews, in its order.
std::vector<RsmView> rsmViews(const capture::Light& light) {
  const float half = glm::radians(light.cone_half_angle_deg);
  if (light.type == capture::Light::Type::Spot && half <= glm::radians(60.0f)) {
    const glm::vec3 dir = glm::normalize(light.direction_world);
    const glm::vec3 up = std::abs(dir.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    return {lookAtView(dir, up, half)};
  }
  const glm::vec3 forward[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  const glm::vec3 up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  std::vector<RsmView> views;
  for (int f = 0; f < 6; ++f) views.push_back(lookAtView(forward[f], up[f], glm::radians(45.0f)));
  return views;
}

// The VPL of texel (x, y) of a view (row 0 at the bottom, as GL stores it), or
// nothing when the texel sees no lit surface. Mirrors the texel loop of Vpls.cpp.
std::optional<ir::Vpl> texelVpl(const reference::RayScene& scene, const capture::Light& light,
                                const RsmView& v, int resolution, int x, int y, double eta) {
  const double tanHalf = std::tan(static_cast<double>(v.halfAngle_rad));
  const double u = (2.0 * (x + 0.5) / resolution - 1.0) * tanHalf;
  const double w = (2.0 * (y + 0.5) / resolution - 1.0) * tanHalf;
  const glm::vec3 direction =
      glm::normalize(v.forward + static_cast<float>(u) * v.right + static_cast<float>(w) * v.up);
  const auto hit = scene.intersect(light.position_world, direction);
  if (!hit) return std::nullopt;
  const glm::vec3 p = hit->position_world;
  const glm::vec3 toSurface = p - light.position_world;
  const float dist = glm::length(toSurface);
  const float profile = light.angularProfile(toSurface / dist);
  if (profile <= 0.0f || dist <= 0.0f) return std::nullopt;
  const double texelSide = 2.0 * tanHalf / resolution;
  const double r2 = 1.0 + u * u + w * w;
  const double solidAngle = texelSide * texelSide / (r2 * std::sqrt(r2));
  const glm::vec3 flux =
      hit->albedo * light.intensity_W_per_sr * static_cast<float>(profile * solidAngle / M_PI);
  if (flux.r + flux.g + flux.b <= 0.0f) return std::nullopt;
  return ir::Vpl{glm::vec4(p, static_cast<float>(eta * dist)), glm::vec4(hit->normal_world, 0.0f),
                 glm::vec4(flux, 0.0f)};
}

}  // namespace

std::vector<ir::Vpl> traceRsmVpls(const reference::RayScene& scene, const capture::Light& light,
                                  int resolution, double indexOfRefraction, int threads) {
  std::vector<ir::Vpl> vpls;
  for (const RsmView& view : rsmViews(light)) {
    // Rows in parallel, then appended in texel order.
    std::vector<std::vector<ir::Vpl>> rows(static_cast<std::size_t>(resolution));
    parallelFor(rows.size(), threads, [&](std::size_t row) {
      for (int x = 0; x < resolution; ++x) {
        const auto vpl =
            texelVpl(scene, light, view, resolution, x, static_cast<int>(row), indexOfRefraction);
        if (vpl) rows[row].push_back(*vpl);
      }
    });
    for (const auto& row : rows) vpls.insert(vpls.end(), row.begin(), row.end());
  }
  return vpls;
}

}  // namespace tofsim::cpu
