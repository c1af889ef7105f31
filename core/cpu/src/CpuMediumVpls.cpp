// The CPU backend's VPL light scattered into the camera rays (issue 42, item
// 4): every VPL of a batch is an emitter for the medium's single scattering
// along each pixel sample's camera ray (before its first surface, or along
// the whole ray when it sees none), by the light's pass's quadrature
// (CpuMediumRays.h, shaders/medium.glsl): its intensity toward the node
// (physics::vplIntensityToward: a surface VPL's cosine emitter or BRDF, a
// medium VPL's albedo x phase), its 1/r^2 bounded by render.indirect's
// geometry clamp (mediumVplRadius), its light starting at its own optical
// path, its visibility the batch's (exact rays or the ISMs, as the surface
// gather's). The physics: core/physics/medium_vpl_scattering.md;
// shaders/medium_vpls.comp is the GL twin. The pairs' roulette is decided a
// block of VPLs at a time by MediumPairFilter.h's bound first (no
// arctangents), then exactly for the pairs it lets through: the same pairs.
#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "CpuIsm.h"
#include "CpuMediumRays.h"
#include "GatherTiles.h"
#include "MediumPairFilter.h"
#include "ParallelFor.h"
#include "ResponseClasses.h"
#include "VplArrays.h"
#include "tofsim/capture/ThinLens.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/MediumRayVpls.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/physics/ScatterVertex.h"
#include "tofsim/physics/ShaderRandom.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/util/Error.h"

namespace tofsim::cpu {

namespace {

/// What the job fixes for every VPL's medium light.
struct VplMediumTerms {
  MediumAxis axis;  ///< start_m: the time axis'; each VPL's path is taken off it
  glm::vec3 sigmaS{0.0f}, sigmaT{0.0f};
  int32_t phase = 0;
  float g = 0.0f;
  float radius = 0.0f;      ///< mediumVplRadius of the geometry clamp, m
  float brdfClamp = 0.0f;   ///< render.indirect.vpl_brdf_clamp, 1/sr
  bool exact = false;       ///< exact visibility rays, else the ISMs (or none)
  float eps = 0.0f;         ///< the exact rays' start offset, m (as the gather's)
  float threshold = 0.0f;   ///< the pairs' roulette (mediumRayThreshold_)
  uint32_t seed = 0;        ///< the pairs' draws (ir::mediumRaySeed)
};

}  // namespace

void CpuBackend::gatherMediumIndirect(std::size_t firstVpl, std::size_t count) {
  // Per-region media: along the rays' stretches inside them (CpuRegionVpls.cpp).
  if (!regions_.empty()) return gatherRegionIndirect(firstVpl, count);
  const capture::RenderSettings& s = job_.settings;
  VplMediumTerms t;
  t.axis = {static_cast<float>(s.time.start_m()), static_cast<float>(s.time.bin_width_m()),
            static_cast<float>(s.time.index_of_refraction), s.time.bins, dropLastLeg_};
  t.sigmaS = s.medium.sigma_s_per_m;
  t.sigmaT = s.medium.sigmaT();
  t.phase = s.medium.phase;
  t.g = s.medium.g;
  t.radius = physics::mediumVplRadius(static_cast<float>(s.indirect.geometry_term_clamp_per_m2));
  t.brdfClamp = static_cast<float>(s.indirect.vpl_brdf_clamp_per_sr);
  t.exact = indirectVisibility_ && s.indirect.visibility == capture::Visibility::Exact;
  t.eps = 1e-4f * sceneScale_m_;  // as the surface gather's exact visibility
  t.threshold = mediumRayThreshold_;
  t.seed = ir::mediumRaySeed(s.seed);
  const CpuIsm* ism = t.exact || !indirectVisibility_ ? nullptr : ism_.get();
  const VplArrays& v = *vpls_;
  const capture::PrimaryRays rays(job_.imager);
  std::optional<capture::ThinLens> lens;
  if (apertureSamples_ > 1) lens.emplace(*capture::cameraOf(job_.imager));
  const bool delayed = !responses_->empty();
  const std::size_t pixel0 = firstPixel_;
  const std::size_t tiles = (pixelCount_ + kTilePixels - 1) / kTilePixels;
  // Each VPL's roulette importance, once (mediumRayVplImportance).
  std::vector<float> importance(v.count);
  for (std::size_t k = firstVpl; k < firstVpl + count; ++k) {
    importance[k] = physics::mediumRayVplImportance(glm::vec3(v.fr[k], v.fg[k], v.fb[k]),
                                                    glm::vec3(v.nx[k], v.ny[k], v.nz[k]));
  }
  parallelFor(tiles, threads_, [&](std::size_t tile) {
    std::vector<MediumSampleRay> samples;
    std::vector<float> classLight(delayed ? static_cast<std::size_t>(t.axis.bins) * kChannels : 0);
    // Per sample, a block's filter verdicts and draws (MediumPairFilter.h).
    std::vector<std::array<int32_t, kVplBlock>> maybe;
    std::vector<std::array<uint32_t, kVplBlock>> draws;
    const std::size_t end = std::min(pixelCount_, (tile + 1) * kTilePixels);
    for (std::size_t i = tile * kTilePixels; i < end; ++i) {
      mediumSampleRays(rays, lens ? &*lens : nullptr, i, samples);
      maybe.resize(samples.size());
      draws.resize(samples.size());
      float* histogram = &mediumIndirect_[i * t.axis.bins * kChannels];
      // VPL by VPL (increasing index), sample by sample, a block at a time.
      for (std::size_t first = firstVpl; first < firstVpl + count; first += kVplBlock) {
        const std::size_t n = std::min(kVplBlock, firstVpl + count - first);
        for (std::size_t j = 0; j < samples.size(); ++j) {
          const PairFilterRay filter{samples[j].origin, samples[j].direction, t.radius,
                                     t.threshold, static_cast<uint32_t>(pixel0 + i),
                                     t.seed + static_cast<uint32_t>(j) * kMediumSampleStride};
          filterMediumPairs(filter, v.px.data(), v.py.data(), v.pz.data(), importance.data(),
                            first, n, maybe[j].data(), draws[j].data());
        }
        for (std::size_t lane = 0; lane < n; ++lane) {
          bool any = false;
          for (std::size_t j = 0; j < samples.size(); ++j) any = any || maybe[j][lane] != 0;
          if (!any) continue;  // no pair of this VPL is kept: it adds nothing
          const std::size_t k = first + lane;
          const glm::vec3 at(v.px[k], v.py[k], v.pz[k]), normal(v.nx[k], v.ny[k], v.nz[k]);
          const glm::vec3 flux(v.fr[k], v.fg[k], v.fb[k]);
          const bool medium = normal == glm::vec3(0.0f);
          const physics::ScatterVertex vertex =
              v.scattering ? v.vertex[k] : physics::ScatterVertex{};
          const glm::vec3 incoming =
              v.scattering ? glm::vec3(v.ix[k], v.iy[k], v.iz[k]) : glm::vec3(0.0f);
          MediumAxis axis = t.axis;
          axis.start_m -= v.path[k];  // the VPL's light starts at its own path
          const auto nodeLight = [&](const physics::MediumNode& nd) {
            const glm::vec3 intensity =
                v.scattering ? physics::vplIntensityToward(vertex, normal, incoming, flux,
                                                           nd.fromLight, t.brdfClamp)
                             : flux * std::max(physics::vplEmitterCosine(normal, nd.fromLight), 0.0f);
            if (intensity == glm::vec3(0.0f)) return glm::vec3(0.0f);
            if (t.exact && scene_->occluded(at + normal * t.eps, nd.x)) {
              return glm::vec3(0.0f);
            }
            // A medium VPL has no hemisphere to map: exact rays among ISMs too
            // (as the surface gather's cullOccludedMediumLanes).
            if (ism && (medium ? scene_->occluded(at, nd.x)
                               : !ism->visible(k, nd.fromLight, nd.r, glm::vec3(0.0f), 1.0f,
                                               sceneScale_m_))) {
              return glm::vec3(0.0f);
            }
            return physics::mediumNodeRadiance(nd, t.sigmaS, t.sigmaT, t.phase, t.g, intensity,
                                               1.0f);
          };
          // Its response class after a medium point (which adds no delay).
          const uint32_t cls =
              delayed ? responseClasses_.then(v.responseClass.empty() ? 0u : v.responseClass[k], 0u)
                      : 0u;
          float* into = cls != 0 ? classLight.data() : histogram;
          for (std::size_t j = 0; j < samples.size(); ++j) {
            if (maybe[j][lane] == 0) continue;
            const MediumSampleRay& r = samples[j];
            const physics::MediumRay ray = physics::mediumEmitterRay(
                r.origin, r.direction, at, t.radius, r.surface, r.lensPath);
            // The pair's draws: kept or not (the exact roulette), and its
            // points' offset.
            const uint32_t bits = draws[j][lane];
            const float q = physics::mediumRayVplSurvival(
                physics::mediumRayVplEstimate(ray, importance[k]), t.threshold);
            if (!(physics::unitFloat(bits) < q)) continue;
            const float offset = physics::unitFloat(physics::pcgHash(bits));
            addSampledMediumRayLight(axis, ray, r.weight / q, offset, into, mediumOutside_[i],
                                     nodeLight);
          }
          if (cls == 0) continue;
          // A delayed class's light goes to its buffer, bin by bin.
          for (int32_t b = 0; b < t.axis.bins; ++b) {
            const glm::vec3 e(classLight[b * kChannels], classLight[b * kChannels + 1],
                              classLight[b * kChannels + 2]);
            if (e != glm::vec3(0.0f)) responses_->depositInBin(i, cls, b, e, mediumOutside_[i]);
          }
          std::fill(classLight.begin(), classLight.end(), 0.0f);
        }
      }
    }
  });
}

}  // namespace tofsim::cpu
