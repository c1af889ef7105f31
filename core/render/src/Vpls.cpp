#include "Vpls.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "GpuScene.h"
#include "SurfaceMaps.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::render {

namespace {

struct RsmView {
  glm::mat4 view;
  float halfAngle_rad;
};

std::vector<RsmView> rsmViews(const capture::Light& light) {
  const glm::vec3 l = light.position_world;
  std::vector<RsmView> views;
  const float half = glm::radians(light.cone_half_angle_deg);
  if (light.type == capture::Light::Type::Spot && half <= glm::radians(60.0f)) {
    const glm::vec3 dir = glm::normalize(light.direction_world);
    const glm::vec3 up = std::abs(dir.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    views.push_back({glm::lookAt(l, l + dir, up), half});
    return views;
  }
  const glm::vec3 forward[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const glm::vec3 up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  for (int f = 0; f < 6; ++f) views.push_back({glm::lookAt(l, l + forward[f], up[f]), glm::radians(45.0f)});
  return views;
}

}  // namespace

std::vector<Vpl> generateVpls(const GpuScene& scene, const capture::Light& light, int resolution,
                              double indexOfRefraction, const glm::vec3& lo, const glm::vec3& hi) {
  std::vector<Vpl> vpls;
  const glm::vec2 range = depthRange(lo, hi, light.position_world);
  SurfaceMaps rsm(resolution, resolution);
  const std::size_t texels = static_cast<std::size_t>(resolution) * resolution;
  std::vector<float> position(texels * 4), normal(texels * 4), albedo(texels * 4);
  for (const RsmView& v : rsmViews(light)) {
    throwIfInterrupted();
    const glm::mat4 projection =
        glm::perspective(2.0f * v.halfAngle_rad, 1.0f, range.x, range.y);
    rsm.render(scene, projection * v.view, light.position_world);
    rsm.position.download(GL_RGBA, GL_FLOAT, position.size() * sizeof(float), position.data());
    rsm.normal.download(GL_RGBA, GL_FLOAT, normal.size() * sizeof(float), normal.data());
    rsm.albedo.download(GL_RGBA, GL_FLOAT, albedo.size() * sizeof(float), albedo.data());
    const double tanHalf = std::tan(static_cast<double>(v.halfAngle_rad));
    const double texelSide = 2.0 * tanHalf / resolution;
    for (int y = 0; y < resolution; ++y) {
      for (int x = 0; x < resolution; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * resolution + x;
        if (position[i * 4 + 3] == 0.0f) continue;
        const glm::vec3 p(position[i * 4], position[i * 4 + 1], position[i * 4 + 2]);
        const glm::vec3 toSurface = p - light.position_world;
        const float dist = glm::length(toSurface);
        const float profile = light.angularProfile(toSurface / dist);
        if (profile <= 0.0f || dist <= 0.0f) continue;
        // Solid angle of the texel on the image plane at unit distance.
        const double u = (2.0 * (x + 0.5) / resolution - 1.0) * tanHalf;
        const double w = (2.0 * (y + 0.5) / resolution - 1.0) * tanHalf;
        const double r2 = 1.0 + u * u + w * w;
        const double solidAngle = texelSide * texelSide / (r2 * std::sqrt(r2));
        const glm::vec3 rho(albedo[i * 4], albedo[i * 4 + 1], albedo[i * 4 + 2]);
        const glm::vec3 flux = rho * light.intensity_W_per_sr *
                               static_cast<float>(profile * solidAngle / M_PI);
        if (flux.r + flux.g + flux.b <= 0.0f) continue;
        const glm::vec3 n(normal[i * 4], normal[i * 4 + 1], normal[i * 4 + 2]);
        vpls.push_back({glm::vec4(p, static_cast<float>(indexOfRefraction * dist)), glm::vec4(n, 0.0f),
                        glm::vec4(flux, 0.0f)});
      }
    }
  }
  return vpls;
}

}  // namespace tofsim::render
