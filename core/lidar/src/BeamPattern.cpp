#include "tofsim/lidar/BeamPattern.h"

#include <algorithm>
#include <cmath>

#include "tofsim/lidar/ScanGrid.h"

namespace tofsim::lidar {

glm::vec3 beamDirection(const LidarSpec& spec, int32_t ring, int32_t azimuth) {
  if (spec.gridScan()) return gridCellDirection(spec, ring, azimuth);
  const double el = glm::radians(spec.elevations_deg.at(static_cast<std::size_t>(ring)));
  const double az = glm::radians(spec.azimuthOf_deg(azimuth));
  const glm::dvec3 up(spec.up_world), forward(spec.forward_world);
  const glm::dvec3 left = glm::cross(up, forward);
  const glm::dvec3 d = std::cos(el) * (std::cos(az) * forward + std::sin(az) * left) +
                       std::sin(el) * up;
  return glm::vec3(glm::normalize(d));
}

double powerRadius_rad(double fraction, double divergence_rad, BeamProfile profile) {
  const double half = 0.5 * divergence_rad;
  if (profile == BeamProfile::Tophat) return half * std::sqrt(fraction);
  // Power within rho of a Gaussian of 1/e^2 radius w: 1 - exp(-2 rho^2 / w^2).
  return half * std::sqrt(-0.5 * std::log1p(-fraction));
}

std::vector<BeamRay> beamRays(int32_t count, double divergence_rad, BeamProfile profile) {
  if (count <= 1) return {BeamRay{}};
  const int32_t rings = std::max(1, static_cast<int32_t>(std::lround(std::sqrt(count) / 2.0)));
  const int32_t sectors = std::max(1, count / rings);
  const float share = 1.0f / static_cast<float>(rings * sectors);
  std::vector<BeamRay> rays;
  rays.reserve(static_cast<std::size_t>(rings * sectors));
  for (int32_t i = 0; i < rings; ++i) {
    const double rho = powerRadius_rad((i + 0.5) / rings, divergence_rad, profile);
    const double turn = (i % 2) * 0.5;
    for (int32_t j = 0; j < sectors; ++j) {
      const double phi = 2.0 * M_PI * (j + turn) / sectors;
      rays.push_back({glm::vec2(static_cast<float>(rho * std::cos(phi)),
                                static_cast<float>(rho * std::sin(phi))),
                      share});
    }
  }
  return rays;
}

BeamFrame beamFrame(const glm::vec3& axis, const glm::vec3& up) {
  glm::vec3 u = glm::cross(up, axis);
  if (glm::dot(u, u) < 1e-12f) {  // a beam along the spin axis: any normal
    u = glm::cross(std::fabs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0), axis);
  }
  u = glm::normalize(u);
  return {axis, u, glm::cross(axis, u)};
}

glm::vec3 rayDirection(const BeamFrame& frame, const glm::vec2& offset_rad) {
  return rayDirection(frame, rayTilt(offset_rad));
}

RayTilt rayTilt(const glm::vec2& offset_rad) {
  const float angle = glm::length(offset_rad);
  if (angle <= 0.0f) return {};
  return {offset_rad / angle, std::tan(angle), false};
}

glm::vec3 rayDirection(const BeamFrame& frame, const RayTilt& tilt) {
  if (tilt.onAxis) return frame.axis;
  return glm::normalize(frame.axis + tilt.tangent * (tilt.unit.x * frame.u + tilt.unit.y * frame.v));
}

}  // namespace tofsim::lidar
