// The CPU backend's VPL light scattered into the camera rays by per-region
// media (issue 42's `media:`; core/physics/medium_vpl_scattering.md, "In
// regions"): the scene-filling medium's sampled pass (CpuMediumVpls.cpp:
// the same roulette over the (ray, VPL) pairs, the same draws, the same
// points of the angle about the VPL) on the ray's stretches inside
// scattering regions (CpuRegionRays.h). Each point is weighted by its
// region's sigma_s and phase function, the camera leg's transmittance to it
// (what the ray crossed before its region, then exp(-sigma_t,r (s - t0)))
// and the VPL -> point leg's passage through the regions, and binned at its
// own path (the VPL's, that leg's with its time in the regions, and the
// camera leg's with its own).
#include <algorithm>
#include <limits>
#include <optional>

#include "CpuIsm.h"
#include "CpuMediumRays.h"
#include "CpuRegionRays.h"
#include "GatherTiles.h"
#include "ParallelFor.h"
#include "ResponseClasses.h"
#include "VplArrays.h"
#include "tofsim/capture/ThinLens.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/MediumRayVpls.h"
#include "tofsim/physics/ScatterVertex.h"
#include "tofsim/physics/ShaderRandom.h"
#include "tofsim/rays/RayScene.h"

namespace tofsim::cpu {

void CpuBackend::gatherRegionIndirect(std::size_t firstVpl, std::size_t count) {
  const capture::RenderSettings& s = job_.settings;
  const MediumAxis axis{static_cast<float>(s.time.start_m()),
                        static_cast<float>(s.time.bin_width_m()),
                        static_cast<float>(s.time.index_of_refraction), s.time.bins, dropLastLeg_};
  const double eta = s.time.index_of_refraction;
  const float radius =
      physics::mediumVplRadius(static_cast<float>(s.indirect.geometry_term_clamp_per_m2));
  const auto brdfClamp = static_cast<float>(s.indirect.vpl_brdf_clamp_per_sr);
  const bool exact = indirectVisibility_ && s.indirect.visibility == capture::Visibility::Exact;
  const float eps = 1e-4f * sceneScale_m_;  // as the surface gather's exact visibility
  const uint32_t seed = ir::mediumRaySeed(s.seed);
  const CpuIsm* ism = exact || !indirectVisibility_ ? nullptr : ism_.get();
  const VplArrays& v = *vpls_;
  const capture::PrimaryRays rays(job_.imager);
  std::optional<capture::ThinLens> lens;
  if (apertureSamples_ > 1) lens.emplace(*capture::cameraOf(job_.imager));
  const bool delayed = !responses_->empty();
  const std::size_t pixel0 = firstPixel_;
  const std::size_t tiles = (pixelCount_ + kTilePixels - 1) / kTilePixels;
  parallelFor(tiles, threads_, [&](std::size_t tile) {
    std::vector<MediumSampleRay> samples;
    std::vector<std::vector<RegionSegment>> segments;
    std::vector<float> classLight(delayed ? static_cast<std::size_t>(axis.bins) * kChannels : 0);
    const std::size_t end = std::min(pixelCount_, (tile + 1) * kTilePixels);
    for (std::size_t i = tile * kTilePixels; i < end; ++i) {
      mediumSampleRays(rays, lens ? &*lens : nullptr, i, samples);
      segments.resize(samples.size());
      bool any = false;
      for (std::size_t j = 0; j < samples.size(); ++j) {
        const MediumSampleRay& r = samples[j];
        regionSegments(regions_, glm::dvec3(r.origin), glm::dvec3(r.direction),
                       r.surface < 0.0f ? std::numeric_limits<double>::infinity()
                                        : static_cast<double>(r.surface),
                       segments[j]);
        any = any || !segments[j].empty();
      }
      if (!any) continue;  // no sample's ray crosses a region
      float* histogram = &mediumIndirect_[i * axis.bins * kChannels];
      physics::OffAxisSums& lost = mediumOutside_[i];
      // VPL by VPL (increasing index), sample by sample, as the medium's pass.
      for (std::size_t k = firstVpl; k < firstVpl + count; ++k) {
        const glm::vec3 at(v.px[k], v.py[k], v.pz[k]), normal(v.nx[k], v.ny[k], v.nz[k]);
        const glm::vec3 flux(v.fr[k], v.fg[k], v.fb[k]);
        const bool medium = normal == glm::vec3(0.0f);
        const physics::ScatterVertex vertex = v.scattering ? v.vertex[k] : physics::ScatterVertex{};
        const glm::vec3 incoming =
            v.scattering ? glm::vec3(v.ix[k], v.iy[k], v.iz[k]) : glm::vec3(0.0f);
        const uint32_t cls =
            delayed ? responseClasses_.then(v.responseClass.empty() ? 0u : v.responseClass[k], 0u)
                    : 0u;
        float* into = cls != 0 ? classLight.data() : histogram;
        const float importance = physics::mediumRayVplImportance(flux, normal);
        for (std::size_t j = 0; j < samples.size(); ++j) {
          if (segments[j].empty()) continue;
          const MediumSampleRay& r = samples[j];
          const physics::MediumRay ray =
              physics::mediumEmitterRay(r.origin, r.direction, at, radius, r.surface, r.lensPath);
          // The pair's draws: kept or not, and its points' offset.
          const uint32_t bits =
              physics::hash3(static_cast<uint32_t>(k), static_cast<uint32_t>(pixel0 + i),
                             seed + static_cast<uint32_t>(j) * kMediumSampleStride);
          const float q = physics::mediumRayVplSurvival(
              physics::mediumRayVplEstimate(ray, importance), mediumRayThreshold_);
          if (!(physics::unitFloat(bits) < q)) continue;
          const float offset = physics::unitFloat(physics::pcgHash(bits));
          for (const RegionSegment& segment : segments[j]) {
            const capture::Medium& m = regions_.medium(segment.region).medium;
            if (!m.scatters()) continue;
            const glm::dvec3 sigmaT(m.sigmaT());
            const double delay = regions_.delayPerMetre(segment.region);
            const physics::MediumInterval iv = physics::mediumSampledInterval(
                ray, glm::vec2(static_cast<float>(segment.t0_m), static_cast<float>(segment.t1_m)));
            for (int step = 0; step < iv.steps; ++step) {
              const physics::MediumNode n =
                  physics::mediumNodeAt(ray, iv, step, glm::vec2(offset, 1.0f));
              if (n.weight == 0.0f) continue;
              const glm::vec3 intensity =
                  v.scattering ? physics::vplIntensityToward(vertex, normal, incoming, flux,
                                                             n.fromLight, brdfClamp)
                               : flux * std::max(physics::vplEmitterCosine(normal, n.fromLight), 0.0f);
              if (intensity == glm::vec3(0.0f)) continue;
              if (exact && scene_->occluded(at + normal * eps, n.x)) continue;
              // A medium VPL has no hemisphere to map: exact rays among ISMs too.
              if (ism && (medium ? scene_->occluded(at, n.x)
                                 : !ism->visible(k, n.fromLight, n.r, glm::vec3(0.0f), 1.0f,
                                                 sceneScale_m_))) {
                continue;
              }
              const capture::RegionPassage leg = regions_.passage(glm::dvec3(at), glm::dvec3(n.x));
              const double along = static_cast<double>(n.s) - segment.t0_m;
              const glm::vec3 camera(glm::exp(-(segment.depthBefore + sigmaT * along)));
              const float scalar = n.weight * physics::phaseFunction(m.phase, m.g, n.cosTheta);
              const glm::vec3 light = m.sigma_s_per_m * intensity *
                                      glm::vec3(leg.transmittance()) * camera * scalar;
              const double path = static_cast<double>(v.path[k]) +
                                  eta * (static_cast<double>(n.r) + leg.extraPath_m + n.s +
                                         r.lensPath + segment.extraBefore_m + delay * along);
              const double bin = std::floor((path - axis.start_m) / axis.width_m);
              physics::depositInBin(
                  into, axis.bins, static_cast<int>(std::clamp(bin, -1.0, double(axis.bins))), 1.0f,
                  light * (r.weight / q), lost);
            }
          }
        }
        if (cls == 0) continue;
        // A delayed class's light goes to its buffer, bin by bin.
        for (int32_t b = 0; b < axis.bins; ++b) {
          const glm::vec3 e(classLight[b * kChannels], classLight[b * kChannels + 1],
                            classLight[b * kChannels + 2]);
          if (e != glm::vec3(0.0f)) responses_->depositInBin(i, cls, b, e, lost);
        }
        std::fill(classLight.begin(), classLight.end(), 0.0f);
      }
    }
  });
}

}  // namespace tofsim::cpu
