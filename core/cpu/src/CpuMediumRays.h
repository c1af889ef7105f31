#pragma once
// What the CPU backend's two medium passes share (issue 42): the light's
// single scattering along the camera rays (CpuMediumDirect.cpp: the bins'
// quadrature nodes) and every VPL's (CpuMediumVpls.cpp: sampled points) use
// shaders/medium.glsl's substitution along each pixel sample's ray; only the
// emitter differs (its position, radius, start path and what it sends toward
// a node, its visibility included), which the caller's node functor gives.

#include <cstdint>
#include <glm/glm.hpp>

#include "tofsim/physics/FootprintBuffer.h"
#include "tofsim/physics/MediumPhysics.h"

namespace tofsim::cpu {

/// The VPLs' pass's draws for a pixel's sample j: the pass's seed plus j
/// times this (ir::mediumRaySeed; medium_vpls.comp's), in the scene medium
/// (CpuMediumVpls.cpp) and in regions (CpuRegionVpls.cpp).
constexpr uint32_t kMediumSampleStride = 0x9e3779b9u;

/// A pixel sample's camera ray as the medium passes integrate along it: the
/// ray traced for the sample (ir::sampleRay), its first surface and weight.
struct MediumSampleRay {
  glm::vec3 origin{0.0f}, direction{0.0f};
  float surface = 0.0f;   ///< distance to its first surface, or MEDIUM_UNBOUNDED
  float lensPath = 0.0f;  ///< the thin lens's path, m (0 with the camera leg untimed)
  float weight = 1.0f;    ///< the sample's share of the pixel
};

/// The time axis as the medium passes bin it: `start_m` is the axis' start
/// less the emitter's own optical path (0 for the light, a VPL's path).
struct MediumAxis {
  float start_m = 0.0f, width_m = 1.0f, eta = 1.0f;
  int32_t bins = 0;
  bool unwarp = false;  ///< the camera leg untimed (CpuBackend::dropLastLeg_)
};

/// The light of bin k's part of a branch's span (k: -1 before the axis, bins
/// after it): `nodeLight(node)` is a node's radiance toward the camera (0
/// where the emitter does not reach it).
template <class NodeLight>
glm::vec3 mediumBinLight(const MediumAxis& a, const physics::MediumRay& ray, int branch,
                         glm::vec2 span, int k, const NodeLight& nodeLight) {
  const glm::vec2 part =
      physics::mediumBinSpan(ray, branch, span, k, a.eta, a.start_m, a.width_m, a.bins);
  const physics::MediumInterval iv = physics::mediumInterval(ray, part);
  glm::vec3 sum(0.0f);
  for (int node = 0; node < iv.steps * iv.nodes; ++node) {
    const physics::MediumNode n = physics::mediumNode(ray, iv, node);
    if (n.weight == 0.0f) continue;
    sum += nodeLight(n);
  }
  return sum;
}

/// A ray's medium light from one emitter times `weight` into a histogram, bin
/// by bin along each branch of monotonic path.
template <class NodeLight>
void addMediumRayLight(const MediumAxis& a, const physics::MediumRay& ray, float weight,
                       float* histogram, physics::OffAxisSums& lost, const NodeLight& nodeLight) {
  const glm::ivec2 branches = physics::mediumBranches(a.unwarp);
  for (int branch = branches.x; branch <= branches.y; ++branch) {
    const glm::vec2 span = physics::mediumSpan(ray, branch);
    if (physics::mediumSpanEmpty(span)) continue;
    const glm::ivec2 bins =
        physics::mediumBinRange(ray, branch, span, a.eta, a.start_m, a.width_m, a.bins);
    const int step = bins.y >= bins.x ? 1 : -1;
    for (int k = bins.x;; k += step) {
      const glm::vec3 light = mediumBinLight(a, ray, branch, span, k, nodeLight);
      physics::depositInBin(histogram, a.bins, k, 1.0f, light * weight, lost);
      if (k == bins.y) break;
    }
  }
}

/// A VPL's sampled light along a ray (medium.glsl, mediumSampledInterval):
/// per branch, MEDIUM_VPL_RAY_SAMPLES points of the angle at `offset` in
/// their steps, each times `weight` into the bin of its own path.
template <class NodeLight>
void addSampledMediumRayLight(const MediumAxis& a, const physics::MediumRay& ray, float weight,
                              float offset, float* histogram, physics::OffAxisSums& lost,
                              const NodeLight& nodeLight) {
  const glm::ivec2 branches = physics::mediumBranches(a.unwarp);
  for (int branch = branches.x; branch <= branches.y; ++branch) {
    const glm::vec2 span = physics::mediumSpan(ray, branch);
    if (physics::mediumSpanEmpty(span)) continue;
    const physics::MediumInterval iv = physics::mediumSampledInterval(ray, span);
    for (int step = 0; step < iv.steps; ++step) {
      const physics::MediumNode n = physics::mediumNodeAt(ray, iv, step, glm::vec2(offset, 1.0f));
      if (n.weight == 0.0f) continue;
      const int k = physics::mediumBinOf(ray, physics::mediumPathAt(ray, branch, n.s), a.eta,
                                         a.start_m, a.width_m, a.bins);
      physics::depositInBin(histogram, a.bins, k, 1.0f, nodeLight(n) * weight, lost);
    }
  }
}

}  // namespace tofsim::cpu
