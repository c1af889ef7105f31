#include "tofsim/ir/RsmTexels.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "tofsim/physics/FootprintKernel.h"
#include "tofsim/physics/MediumPhysics.h"

namespace tofsim::ir {

namespace {

RsmView lookAtView(const glm::vec3& forward, const glm::vec3& upHint, float half) {
  const glm::vec3 f = glm::normalize(forward);
  const glm::vec3 s = glm::normalize(glm::cross(f, upHint));
  return {f, s, glm::cross(s, f), upHint, half, std::tan(static_cast<double>(half))};
}

// Image-plane coordinates (at unit distance along forward) of texel (x, y)'s centre.
glm::dvec2 texelPlanePoint(const RsmView& v, int resolution, int x, int y) {
  const double tanHalf = v.tanHalf;
  return {(2.0 * (x + 0.5) / resolution - 1.0) * tanHalf,
          (2.0 * (y + 0.5) / resolution - 1.0) * tanHalf};
}

}  // namespace

glm::mat4 RsmView::viewMatrix(const glm::vec3& light_world) const {
  return glm::lookAt(light_world, light_world + forward, upHint);
}

std::vector<RsmView> rsmViews(const capture::Light& light) {
  const float half = glm::radians(light.cone_half_angle_deg);
  if (light.type == capture::Light::Type::Spot && half <= glm::radians(60.0f)) {
    const glm::vec3 dir = glm::normalize(light.direction_world);
    const glm::vec3 up = std::abs(dir.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    return {lookAtView(dir, up, half)};
  }
  if (light.type == capture::Light::Type::Lambertian) {
    // The hemisphere in front of the emitter: a cube about its normal without
    // the back face; the side faces' back halves get no VPL (profile 0).
    const glm::vec3 n = glm::normalize(light.direction_world);
    const glm::vec3 t = glm::normalize(
        glm::cross(n, std::abs(n.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
    const glm::vec3 b = glm::cross(n, t);
    const float quarter = glm::radians(45.0f);
    return {lookAtView(n, b, quarter), lookAtView(t, n, quarter), lookAtView(-t, n, quarter),
            lookAtView(b, n, quarter), lookAtView(-b, n, quarter)};
  }
  const glm::vec3 forward[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  const glm::vec3 up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  std::vector<RsmView> views;
  for (int f = 0; f < 6; ++f) views.push_back(lookAtView(forward[f], up[f], glm::radians(45.0f)));
  return views;
}

glm::vec3 rsmTexelDirection(const RsmView& view, int resolution, int x, int y) {
  const glm::dvec2 p = texelPlanePoint(view, resolution, x, y);
  return glm::normalize(view.forward + static_cast<float>(p.x) * view.right +
                        static_cast<float>(p.y) * view.up);
}

std::optional<Vpl> rsmTexelVpl(const capture::Light& light, const RsmView& view, int resolution,
                               int x, int y, const RsmTexelSurface& surface,
                               double indexOfRefraction) {
  const glm::vec3 p = surface.position_world;
  const glm::vec3 toSurface = p - light.position_world;
  const float dist = glm::length(toSurface);
  if (!(dist > 0.0f)) return std::nullopt;
  const float profile = light.angularProfile(toSurface / dist);
  if (profile <= 0.0f) return std::nullopt;
  // Solid angle of the texel: its area on the unit-distance plane times cos^3.
  const double texelSide = 2.0 * view.tanHalf / resolution;
  const glm::dvec2 q = texelPlanePoint(view, resolution, x, y);
  const double r2 = 1.0 + q.x * q.x + q.y * q.y;
  const double solidAngle = texelSide * texelSide / (r2 * std::sqrt(r2));
  const bool holdsScatter = physics::vplFluxHoldsScatter(surface.vertex);
  const glm::vec3 flux = holdsScatter
                             ? glm::vec3(surface.vertex.color) * light.intensity_W_per_sr *
                                   static_cast<float>(profile * solidAngle / M_PI)
                             : light.intensity_W_per_sr * static_cast<float>(profile * solidAngle);
  if (flux.r + flux.g + flux.b <= 0.0f) return std::nullopt;
  // The texel's patch on the surface: the surface point's steps across one
  // texel (ray differentials, as for a camera pixel), and the light leg's
  // part of the path's change along each (footprint_kernel.md).
  const auto eta = static_cast<float>(indexOfRefraction);
  const auto side = static_cast<float>(texelSide);
  const glm::vec3 stepU =
      physics::surfaceStepAcrossPixel(toSurface, view.forward, view.right * side, surface.normal);
  const glm::vec3 stepV =
      physics::surfaceStepAcrossPixel(toSurface, view.forward, view.up * side, surface.normal);
  const glm::vec3 fromLight = toSurface / dist;
  Vpl vpl{glm::vec4(p, static_cast<float>(indexOfRefraction * dist)),
          glm::vec4(surface.normal, 0.0f), glm::vec4(flux, 0.0f),
          glm::vec4(stepU, eta * glm::dot(fromLight, stepU)),
          glm::vec4(stepV, eta * glm::dot(fromLight, stepV))};
  vpl.vertex = surface.vertex;
  if (!holdsScatter) vpl.incoming = glm::vec4(-fromLight, 0.0f);
  return vpl;
}

void attenuateLightLegs(std::vector<Vpl>& vpls, const capture::MediumRegions& regions,
                        const glm::vec3& light_world, double indexOfRefraction) {
  if (regions.empty()) return;
  for (Vpl& v : vpls) {
    const capture::RegionPassage leg =
        regions.passage(glm::dvec3(light_world), glm::dvec3(v.positionPath));
    v.flux = glm::vec4(glm::vec3(v.flux) * glm::vec3(leg.transmittance()), v.flux.w);
    v.positionPath.w += static_cast<float>(indexOfRefraction * leg.extraPath_m);
  }
}

void attenuateLightLegs(std::vector<Vpl>& vpls, const capture::Medium& medium,
                        double indexOfRefraction) {
  if (!medium.present()) return;
  const glm::vec3 sigmaT = medium.sigmaT();
  const auto eta = static_cast<float>(indexOfRefraction);
  for (Vpl& v : vpls) {
    const glm::vec3 t = physics::mediumTransmittance(sigmaT, v.positionPath.w / eta);
    v.flux = glm::vec4(glm::vec3(v.flux) * t, v.flux.w);  // w: the response class
  }
}

}  // namespace tofsim::ir
