#pragma once
// Medium VPLs (issue 42, item 4; physics in core/physics/medium_vpls.md):
// where the light's paths scatter in a scattering medium filling the scene
// before they reach a surface. The light's own rays make the first bounce's
// (lightMediumVpls, appended after the RSM's VPLs); a later bounce's ray may
// end in the medium too (traceBounce, by sampleFreeFlight). Backend-
// independent: the rays are the driver's Embree scene's.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "tofsim/capture/Light.h"
#include "tofsim/capture/Medium.h"
#include "tofsim/capture/MediumRegions.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/physics/ResponseClassTable.h"

namespace tofsim::rays {
class RayScene;
}

namespace tofsim::ir {

/// Where a ray of the light's power ends in the medium: a distance drawn from
/// exp(-sigma t) in the channel mean sigma of sigma_t, and per channel the
/// weight that keeps each channel's estimate unbiased.
struct FreeFlight {
  bool inMedium = false;  ///< at t in the medium; false: it reaches its hit
  double t_m = 0.0;       ///< distance along the ray (inMedium only)
  /// inMedium: the power extinguished at t per unit power carried, over the
  /// pdf of t: sigma_t exp(-sigma_t t) / pdf(t). Else: the transmittance to
  /// the hit over the probability of getting there, exp(-sigma_t D) / P(t >= D).
  glm::vec3 weight{1.0f};
};

/// No hit: the ray leaves the scene (D infinite).
constexpr double kNoHit = std::numeric_limits<double>::infinity();

/// A free flight along a ray whose first surface is at `hit_m` (kNoHit:
/// none), from one uniform number u in [0, 1). `truncated`: t is drawn in
/// [0, hit_m) (pdf sigma exp(-sigma t) / (1 - exp(-sigma D))), always in the
/// medium (the light's medium VPLs: the RSM's VPLs stand for the light that
/// reaches the surfaces); otherwise t < hit_m with probability
/// 1 - exp(-sigma D), else the ray reaches its hit (a later bounce's child).
/// A medium with sigma_t = 0 in every channel never stops a ray.
FreeFlight sampleFreeFlight(const capture::Medium& medium, double hit_m, bool truncated, double u);

/// The first bounce's medium VPLs: `count` rays from `light`, drawn from its
/// emission profile (a point light's sphere, a spot's cone, a cosine
/// emitter's hemisphere), each carrying intensity x profile / pdf / count of
/// power, each with its own generator (seed, index: the bytes do not depend
/// on `threads`), traced through `scene`; each makes one medium VPL
/// (ir::mediumVpl) at a free-flight distance in [0, D) (sampleFreeFlight,
/// truncated), its flux the power extinguished there, its path eta t, its
/// incoming direction toward the light, its class the first bounce's
/// (vplClassAfter(classes, 0, its vertex); none: 0). Empty unless the medium
/// scatters (capture::Medium::scatters).
std::vector<Vpl> lightMediumVpls(const rays::RayScene& scene, const capture::Light& light,
                                 const capture::Medium& medium, std::size_t count, uint64_t seed,
                                 double indexOfRefraction, int32_t threads = 1,
                                 const physics::ResponseClassTable* classes = nullptr);

/// The first bounce's medium VPLs in per-region media (`media:`): `count`
/// rays from `light` as lightMediumVpls', each through the regions to its
/// first surface (LegFlight); a ray that crosses a scattering region makes
/// one medium VPL at an event drawn before that surface
/// (LegFlight::sampleBeforeEnd: always in a region), its flux the power
/// extinguished there over the event's density, its vertex its region's
/// (albedo, phase function), its path eta (t + the time spent in regions).
/// The RSM's VPLs stand for the light that reaches the surfaces (attenuated
/// by attenuateLightLegs). Empty unless some region scatters.
std::vector<Vpl> lightRegionVpls(const rays::RayScene& scene, const capture::Light& light,
                                 const capture::MediumRegions& regions, std::size_t count,
                                 uint64_t seed, double indexOfRefraction, int32_t threads = 1,
                                 const physics::ResponseClassTable* classes = nullptr);

}  // namespace tofsim::ir
