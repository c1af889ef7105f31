#pragma once
// VPLs of the indirect bounces after the first (Keller 1997, "Instant
// radiosity"): the RSM gives bounce 1; the VPLs of bounce k + 1 continue the
// light paths of those of bounce k by cosine-weighted directions (sampled
// from the VPL's BRDF for glossy VPLs) traced against the scene, so every VPL still carries its
// flux and its whole optical path from the light, and the gather needs nothing new.
// Backend-independent: the rays are Embree's whatever device gathers.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tofsim/capture/Medium.h"
#include "tofsim/capture/MediumRegions.h"
#include "tofsim/capture/RegionScattering.h"
#include "tofsim/capture/RenderJob.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/physics/ResponseClassTable.h"

namespace tofsim::rays {
class RayScene;
}

namespace tofsim::ir {

/// All VPLs of a render, bounce 1 first, then 2, ...: bounce k (1-based) is
/// vpls[firstOfBounce[k - 1], firstOfBounce[k]).
struct BouncedVpls {
  std::vector<Vpl> vpls;
  std::vector<std::size_t> firstOfBounce;  ///< bounces + 1 offsets, the last = vpls.size()

  int32_t bounces() const { return static_cast<int32_t>(firstOfBounce.size()) - 1; }
  std::size_t countOf(int32_t bounce) const {
    return firstOfBounce[bounce] - firstOfBounce[bounce - 1];
  }
};

/// How a bounce's rays are traced.
struct BounceTracing {
  /// A child survives with probability q = its hit's largest albedo
  /// channel, its flux divided by q (IndirectSettings::russian_roulette).
  bool russian_roulette = false;
  /// Threads over fixed runs of rays; 0 = all. The bytes do not depend on it.
  int32_t threads = 1;
  /// The medium filling the scene (RenderSettings::medium): a child's flux
  /// is attenuated over its parent -> child leg, exp(-sigma_t |x - x_parent|).
  /// Where it scatters (Medium::scatters) the leg is a free flight instead
  /// (ir::sampleFreeFlight): the child may be a medium VPL where the ray
  /// scatters before its hit (core/physics/medium_vpls.md).
  capture::Medium medium{};
  /// Per-region media (RenderSettings::media joined with the scene; null or
  /// empty: none): a child's parent -> child leg through them is attenuated
  /// by its transmittance and delayed by the time it spends in them
  /// (capture::RegionPassage), as the RSM VPLs' light legs are
  /// (ir::attenuateLightLegs).
  const capture::MediumRegions* regions = nullptr;
};

/// How later bounces reflect (render.materials, render.indirect.vpl_brdf_clamp).
struct BounceMaterials {
  int vertexModel = physics::VERTEX_LAMBERTIAN;  ///< of the children's vertices (Vpl::vertex)
  float brdfClamp = 0.0f;                        ///< 1/sr, <= 0: none
  /// Each child's response class (Vpl::flux.w, VplClasses.h) from its
  /// parent's and its hit's; null: none (flux.w 0).
  const physics::ResponseClassTable* classes = nullptr;
};

/// The VPLs of one bounce after `parents` (those of bounce `bounce` - 1):
/// `count` children picked among the parents in proportion to their power
/// (systematic resampling, one seeded offset per bounce: deterministic, and
/// every parent of power p gets count * p / total children on average), each
/// shot from its parent in a cosine-weighted direction (a BRDF-sampled one
/// for glossy VPLs, below; its own seeded
/// generator, from the seed, the bounce and its index). A child sits at the
/// first hit, its normal facing the ray, its path the parent's plus eta times
/// the leg, its flux albedo * (the total power / count) / pi in the parent's
/// colour: the expected power of the bounce is the albedo times the parents'.
/// Rays that leave the scene make no VPL; with Russian roulette a child
/// that loses makes none either. Children have no RSM patch
/// (patchU = patchV = 0: a point VPL, no VPL footprint): a child stands for
/// the parents' light spread over the scene by a random ray, not for a texel
/// of a light view whose extent the patch steps could describe.
/// With materials.gltf the VPLs are glossy (flux = the power received, W): w
/// is drawn from the parent's BRDF (physics::sampleGltfMixture about
/// parent.incoming), the child receives its share times f cos / pdf (f
/// clamped by brdfClamp; a w below the surface ends the path; the parents
/// are still picked by the power they received, which stays unbiased), and
/// records -w and its hit's material.
/// A medium parent (ir::isMediumVpl) shoots by its phase function about the
/// direction its light travelled (physics::samplePhaseDirection; weight: the
/// albedo); in a scattering medium each child's ray takes a free flight
/// (BounceTracing::medium).
std::vector<Vpl> traceBounce(const rays::RayScene& scene, const std::vector<Vpl>& parents,
                             std::size_t count, int32_t bounce, uint64_t seed,
                             double indexOfRefraction, const BounceTracing& tracing = {},
                             const BounceMaterials& materials = {});

/// Whether a render traces the light's medium VPLs (indirect light,
/// render.indirect.medium_vpls > 0 and a scattering medium or region).
inline bool lightMediumVplsWanted(const capture::RenderSettings& s) {
  return s.indirect.enabled && s.indirect.medium_vpls > 0 &&
         (s.medium.scatters() || capture::regionsScatter(s));
}

/// Bounce 1 (`firstBounce`, the backend's RSM VPLs, then with a scattering
/// medium render.indirect.medium_vpls of the light's medium VPLs,
/// ir::lightMediumVpls, or with scattering regions ir::lightRegionVpls)
/// followed by bounces
/// 2..job.settings.indirect.bounces, traced through `scene` (the driver's
/// RayScene of job.scene), on indirect.trace_threads threads. Bounce 2 traces vpls_per_bounce rays
/// (0: as many as bounce 1 has VPLs), and so does every later bounce, or with russian_roulette as
/// many as the bounce before kept. `classes`: the later bounces' response
/// classes from the first bounce's (flux.w; null: none).
BouncedVpls withLaterBounces(const capture::RenderJob& job, const rays::RayScene& scene,
                             std::vector<Vpl> firstBounce,
                             const physics::ResponseClassTable* classes = nullptr);
/// The same through a RayScene of job.scene built here (only when there is a
/// later bounce and light to continue, or medium VPLs to trace): for callers
/// without a driver.
BouncedVpls withLaterBounces(const capture::RenderJob& job, std::vector<Vpl> firstBounce,
                             const physics::ResponseClassTable* classes = nullptr);

}  // namespace tofsim::ir
