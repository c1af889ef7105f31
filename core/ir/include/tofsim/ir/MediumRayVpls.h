#pragma once
// The roulette of the VPLs' light in the camera rays (issue 42, item 4;
// core/physics/medium_vpl_scattering.md, "Sampled"): each backend keeps a
// (ray, VPL) pair with probability min(1, estimate / threshold) and weighs it
// by the inverse (shaders/medium.glsl, mediumRayVplSurvival). The threshold
// is the render's, from all its VPLs, so that a pair's draw does not depend
// on how the batches split them.

#include <cstdint>
#include <vector>

#include "tofsim/capture/RegionScattering.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/physics/ShaderRandom.h"

namespace tofsim::ir {

/// Whether the VPLs' light scatters into the camera rays: a scattering medium
/// (RenderSettings::vplsLightCameraRays) or, on the CPU backend, a
/// scattering region (along the rays' stretches inside it), with
/// render.indirect.medium_camera_rays.
inline bool vplsLightCameraRays(const capture::RenderSettings& settings) {
  return settings.vplsLightCameraRays() ||
         (capture::regionsScatter(settings) && settings.indirect.medium_camera_rays);
}

/// The threshold for `vpls` in a scene of diagonal `sceneScale_m`: the sum of
/// their estimates for a ray passing each at a quarter of the scene's scale
/// (the full line's angle pi over that height), over
/// MEDIUM_VPL_RAY_PAIRS; 0 (every pair kept) with at most that many VPLs.
inline float mediumRayThreshold(const std::vector<Vpl>& vpls, float sceneScale_m) {
  if (static_cast<float>(vpls.size()) <= physics::MEDIUM_VPL_RAY_PAIRS) return 0.0f;
  double sum = 0.0;
  for (const Vpl& v : vpls) {
    sum += physics::mediumRayVplImportance(glm::vec3(v.flux), glm::vec3(v.normal));
  }
  const double perPair = physics::PI / (0.25 * static_cast<double>(sceneScale_m));
  return static_cast<float>(sum * perPair / physics::MEDIUM_VPL_RAY_PAIRS);
}

/// The pairs' draws' seed from render.seed (folded to 32 bits as the ISMs'
/// uSeed, then set apart from its other uses): both backends hash (VPL
/// index, pixel, this + the sample's index x 0x9e3779b9).
inline uint32_t mediumRaySeed(uint64_t seed) {
  return physics::pcgHash(static_cast<uint32_t>(seed ^ (seed >> 32)) ^ 0x6d656469u);
}

}  // namespace tofsim::ir
