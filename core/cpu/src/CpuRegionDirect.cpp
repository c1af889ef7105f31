// The CPU backend's single scattering in per-region media (issue 42's
// `media:`; core/physics/medium_single_scattering.md, "In regions"): the
// light that scattering regions scatter once into each pixel sample's camera
// ray, along the ray's stretches inside them (CpuRegionRays.h) before its
// first surface. The scene-filling medium's pass (CpuMediumDirect.cpp) with
// the integrand made piecewise: inside region r sigma_s and the phase
// function are r's, the camera leg's transmittance is what the ray crossed
// before r times exp(-sigma_t,r (s - t0)), the light leg's is its passage
// through the regions (MediumRegions, per node), and the time adds each
// leg's extra path in the regions (eta_r / eta_axis - 1 per metre inside).
// Each bin's part of a stretch is found in s (its edges by regula falsi on
// the nondecreasing path) and integrated by the same Gauss-Legendre nodes in
// the angle about the light (physics::mediumInterval, mediumNode): the bin's
// integral, not points. Direct light (one scattering event), into the same
// histograms and off-axis sums, each pixel by one thread.
#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

#include "CpuDirectConstants.h"
#include "CpuMediumRays.h"
#include "CpuRegionRays.h"
#include "GatherTiles.h"
#include "ParallelFor.h"
#include "tofsim/capture/ThinLens.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/physics/FootprintBuffer.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/rays/RayScene.h"

namespace tofsim::cpu {

namespace {

// The bin of geometric path q (metres at the axis' index), -1 before the
// axis and `bins` after it.
int axisBinOf(const MediumAxis& a, double q) {
  const double k = std::floor((static_cast<double>(a.eta) * q - a.start_m) / a.width_m);
  return static_cast<int>(std::clamp(k, -1.0, static_cast<double>(a.bins)));
}

// One region segment's single scattering, bin by bin, times `weight` into
// `histogram`. `ray`: the camera ray toward the light (physics::mediumRay);
// `nodeLight(node, region)`: a node's radiance toward the camera with the
// light leg's visibility and passage, before the camera leg's
// transmittance, which is added here.
template <class NodeLight>
void addRegionSegmentLight(const MediumAxis& a, const physics::MediumRay& ray,
                           const RegionSegment& segment, const RegionSegmentPath& path,
                           const glm::dvec3& sigmaT, float weight, float* histogram,
                           physics::OffAxisSums& lost, const NodeLight& nodeLight) {
  double lo = segment.t0_m, pathLo = path.at(lo);
  const double end = segment.t1_m, pathEnd = path.at(end);
  const int first = axisBinOf(a, pathLo), last = std::max(first, axisBinOf(a, pathEnd));
  for (int k = first; k <= last; ++k) {
    double hi = end, pathHi = pathEnd;
    if (k < last) {  // the bin's upper edge, between the part's start and the segment's end
      const double q = (static_cast<double>(a.start_m) + (k + 1) * static_cast<double>(a.width_m)) /
                       static_cast<double>(a.eta);
      hi = path.sAt(q, lo, pathLo, end, pathEnd);
      pathHi = path.at(hi);
    }
    const physics::MediumInterval iv =
        physics::mediumInterval(ray, glm::vec2(static_cast<float>(lo), static_cast<float>(hi)));
    glm::vec3 sum(0.0f);
    for (int node = 0; node < iv.steps * iv.nodes; ++node) {
      const physics::MediumNode n = physics::mediumNode(ray, iv, node);
      if (n.weight == 0.0f) continue;
      const glm::dvec3 depth =
          segment.depthBefore + sigmaT * (static_cast<double>(n.s) - segment.t0_m);
      sum += nodeLight(n) * glm::vec3(glm::exp(-depth));
    }
    physics::depositInBin(histogram, a.bins, k, 1.0f, sum * weight, lost);
    lo = hi;
    pathLo = pathHi;
  }
}

}  // namespace

void CpuBackend::gatherRegionDirect() {
  const DirectConstants c = directConstants();
  const MediumAxis axis{c.start_m, c.width_m, c.eta, c.bins, dropLastLeg_};
  const capture::PrimaryRays rays(job_.imager);
  std::optional<capture::ThinLens> lens;
  if (apertureSamples_ > 1) lens.emplace(*capture::cameraOf(job_.imager));
  const glm::dvec3 light(c.light_world);
  const std::size_t tiles = (pixelCount_ + kTilePixels - 1) / kTilePixels;
  parallelFor(tiles, threads_, [&](std::size_t tile) {
    std::vector<MediumSampleRay> samples;
    std::vector<RegionSegment> segments;
    const std::size_t end = std::min(pixelCount_, (tile + 1) * kTilePixels);
    for (std::size_t i = tile * kTilePixels; i < end; ++i) {
      mediumSampleRays(rays, lens ? &*lens : nullptr, i, samples);
      float* histogram = &direct_[i * c.bins * kChannels];
      for (const MediumSampleRay& r : samples) {
        const glm::dvec3 origin(r.origin), dir(r.direction);
        regionSegments(regions_, origin, dir,
                       r.surface < 0.0f ? std::numeric_limits<double>::infinity()
                                        : static_cast<double>(r.surface),
                       segments);
        const physics::MediumRay ray =
            physics::mediumRay(r.origin, r.direction, c.light_world, r.surface, r.lensPath);
        for (const RegionSegment& segment : segments) {
          const capture::Medium& m = regions_.medium(segment.region).medium;
          if (!m.scatters()) continue;
          // A node's light: the light's profile toward it, a shadow ray, the
          // light leg's passage through the regions, the region's scattering.
          const auto nodeLight = [&](const physics::MediumNode& n) {
            const float profile =
                physics::lightProfile(c.profile.kind, c.profile.axis, c.profile.cosOuter,
                                      c.profile.cosInner, n.fromLight);
            if (profile <= 0.0f || scene_->occluded(n.x, c.light_world)) return glm::vec3(0.0f);
            const glm::vec3 toLight(regions_.passage(glm::dvec3(n.x), light).transmittance());
            const float scalar = n.weight * physics::phaseFunction(m.phase, m.g, n.cosTheta) * profile;
            return m.sigma_s_per_m * c.intensity_W_per_sr * toLight * scalar;
          };
          const RegionSegmentPath path(regions_, segment, origin, dir, light, r.lensPath);
          addRegionSegmentLight(axis, ray, segment, path, glm::dvec3(m.sigmaT()), r.weight,
                                histogram, outside_[i], nodeLight);
        }
      }
    }
  });
}

}  // namespace tofsim::cpu
