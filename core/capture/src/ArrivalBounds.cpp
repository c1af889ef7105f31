#include "tofsim/capture/ArrivalBounds.h"

#include <algorithm>
#include <array>

#include "tofsim/util/Error.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::capture {

namespace {

using Corners = std::array<glm::dvec3, 8>;

Corners cornersOf(const scene::Bounds& box) {
  Corners corners;
  for (int i = 0; i < 8; ++i) {
    corners[i] = glm::dvec3((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                            (i & 4) ? box.max.z : box.min.z);
  }
  return corners;
}

double distanceToBox(const glm::dvec3& p, const scene::Bounds& box) {
  const glm::dvec3 nearest = glm::clamp(p, glm::dvec3(box.min), glm::dvec3(box.max));
  return glm::length(p - nearest);
}

// Longest light -> x1 -> ... -> xn (-> camera) over corner tuples: best[k] is
// the longest path of the current length that ends at corner k.
double longestThroughCorners(const glm::dvec3& light, const glm::dvec3& camera,
                             const Corners& corners, int32_t vertices, bool toCamera) {
  std::array<double, 8> best{};
  for (int k = 0; k < 8; ++k) best[k] = glm::length(corners[k] - light);
  for (int32_t n = 1; n < vertices; ++n) {
    std::array<double, 8> next{};
    for (int k = 0; k < 8; ++k) {
      for (int j = 0; j < 8; ++j) {
        next[k] = std::max(next[k], best[j] + glm::length(corners[k] - corners[j]));
      }
    }
    best = next;
  }
  double longest = 0.0;
  for (int k = 0; k < 8; ++k) {
    longest = std::max(longest, best[k] + (toCamera ? glm::length(camera - corners[k]) : 0.0));
  }
  return longest;
}

// Whether the light can be seen straight by the camera: it projects into the
// image and the spot cone points at the camera (occlusion is not known here).
bool lightMayBeSeen(const RenderJob& job) {
  if (cameraOf(job.imager) == nullptr) return false;  // as directLightView
  const glm::vec3 toCamera = job.camera().position_world - job.light.position_world;
  const float d = glm::length(toCamera);
  if (d <= 1e-6f || job.camera().project(job.light.position_world).x < 0) return false;
  return job.light.angularProfile(toCamera / d) > 0.0f;
}

}  // namespace

double ArrivalBounds::shortest_s() const { return shortest_m / kSpeedOfLight_m_per_s; }
double ArrivalBounds::longest_s() const { return longest_m / kSpeedOfLight_m_per_s + delay_s; }

ArrivalBounds arrivalBounds(const RenderJob& job, int32_t surfaceVertices) {
  TOFSIM_CHECK(job.scene != nullptr && surfaceVertices >= 1);
  const bool unwarp = job.settings.time.camera_unwarp || !lastLegCounts(job.imager);
  const double eta = job.settings.time.index_of_refraction;
  const glm::dvec3 light(job.light.position_world);
  ArrivalBounds bounds;
  if (job.scene->triangleCount() > 0) {
    const scene::Bounds box = job.scene->bounds();
    const double in = distanceToBox(light, box);
    // A defocused camera's legs end anywhere on its aperture disk, within
    // its radius of the centre, and add the lens's path, within the radius
    // of the chief ray's (ThinLens.h): a diameter either way.
    const Camera* c = cameraOf(job.imager);
    const double aperture = c != nullptr && !unwarp ? c->aperture_m : 0.0;
    // The union over every point a last leg may end at.
    for (const glm::vec3& end : viewpoints(job.imager)) {
      const glm::dvec3 camera(end);
      const double straight = glm::length(light - camera);
      const double shortest = unwarp ? in : std::max(straight, in + distanceToBox(camera, box));
      const double longest =
          longestThroughCorners(light, camera, cornersOf(box), surfaceVertices, !unwarp);
      const double lo = eta * std::max(0.0, shortest - aperture), hi = eta * (longest + aperture);
      bounds = bounds.any ? ArrivalBounds{true, std::min(bounds.shortest_m, lo),
                                          std::max(bounds.longest_m, hi)}
                          : ArrivalBounds{true, lo, hi};
    }
  }
  if (lightMayBeSeen(job)) {
    // Unwarped time is the time at the scene point; the source emits at 0.
    const double seen_m =
        unwarp ? 0.0 : eta * glm::length(light - glm::dvec3(job.camera().position_world));
    bounds.shortest_m = bounds.any ? std::min(bounds.shortest_m, seen_m) : seen_m;
    bounds.longest_m = bounds.any ? std::max(bounds.longest_m, seen_m) : seen_m;
    bounds.any = true;
  }
  return bounds;
}

}  // namespace tofsim::capture
