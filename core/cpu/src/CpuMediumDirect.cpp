// The CPU backend's medium pass (issue 42, item 3): the light the medium
// filling the scene scatters once into each pixel sample's camera ray before
// its first surface (along the whole ray when it sees none), per time bin, by
// shaders/medium.glsl's quadrature; the light's visibility at each node is a
// shadow ray, as the direct gather's. Direct light (one scattering event),
// added after the surfaces' into the same histograms and off-axis sums, each
// pixel by one thread. shaders/medium_direct.comp is the GL twin; the
// physics and its accuracy: core/physics/medium_single_scattering.md.
#include <algorithm>
#include <optional>

#include "GatherKernel.h"
#include "GatherTiles.h"
#include "ParallelFor.h"
#include "tofsim/capture/ThinLens.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/physics/FootprintBuffer.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/physics/TransientPhysics.h"
#include "tofsim/rays/RayScene.h"

namespace tofsim::cpu {

namespace {

/// What the medium, the light and the time axis fix for every ray.
struct MediumTerms {
  glm::vec3 sigmaS{0.0f}, sigmaT{0.0f};
  int32_t phase = 0;
  float g = 0.0f;
  capture::Light::ProfileTerms profile;
  glm::vec3 light{0.0f};
  glm::vec3 intensity{0.0f};
  float start_m = 0.0f, width_m = 1.0f, eta = 1.0f;
  int32_t bins = 0;
  bool unwarp = false;  ///< the camera leg untimed (CpuBackend::dropLastLeg_)
};

MediumTerms mediumTerms(const capture::RenderJob& job, bool dropLastLeg) {
  const capture::RenderSettings& s = job.settings;
  MediumTerms m;
  m.sigmaS = s.medium.sigma_s_per_m;
  m.sigmaT = s.medium.sigmaT();
  m.phase = s.medium.phase;
  m.g = s.medium.g;
  m.profile = job.light.profileTerms();
  m.light = job.light.position_world;
  m.intensity = job.light.intensity_W_per_sr;
  m.start_m = static_cast<float>(s.time.start_m());
  m.width_m = static_cast<float>(s.time.bin_width_m());
  m.eta = static_cast<float>(s.time.index_of_refraction);
  m.bins = s.time.bins;
  m.unwarp = dropLastLeg;
  return m;
}

/// The light of bin k's part of a branch's span (k: -1 before the axis,
/// bins after it).
glm::vec3 binLight(const MediumTerms& m, const rays::RayScene& scene,
                   const physics::MediumRay& ray, int branch, glm::vec2 span, int k) {
  const physics::MediumInterval iv = physics::mediumInterval(
      ray, physics::mediumBinSpan(ray, branch, span, k, m.eta, m.start_m, m.width_m, m.bins));
  glm::vec3 sum(0.0f);
  for (int node = 0; node < iv.steps * physics::MEDIUM_GAUSS_NODES; ++node) {
    const physics::MediumNode n = physics::mediumNode(ray, iv, node);
    const float profile = physics::lightProfile(m.profile.kind, m.profile.axis, m.profile.cosOuter,
                                                m.profile.cosInner, n.fromLight);
    // A medium point has no surface to leave: the shadow ray starts at it.
    if (profile <= 0.0f || n.weight == 0.0f || scene.occluded(n.x, m.light)) continue;
    sum += physics::mediumNodeRadiance(n, m.sigmaS, m.sigmaT, m.phase, m.g, m.intensity, profile);
  }
  return sum;
}

/// A ray's medium light times `weight` (its share of the pixel) into a
/// pixel's histogram, bin by bin along each branch of monotonic path.
void addRayLight(const MediumTerms& m, const rays::RayScene& scene, const physics::MediumRay& ray,
                 float weight, float* histogram, physics::OffAxisSums& lost) {
  const glm::ivec2 branches = physics::mediumBranches(m.unwarp);
  for (int branch = branches.x; branch <= branches.y; ++branch) {
    const glm::vec2 span = physics::mediumSpan(ray, branch);
    if (physics::mediumSpanEmpty(span)) continue;
    const glm::ivec2 bins =
        physics::mediumBinRange(ray, branch, span, m.eta, m.start_m, m.width_m, m.bins);
    const int step = bins.y >= bins.x ? 1 : -1;
    for (int k = bins.x;; k += step) {
      const glm::vec3 light = binLight(m, scene, ray, branch, span, k);
      physics::depositInBin(histogram, m.bins, k, 1.0f, light * weight, lost);
      if (k == bins.y) break;
    }
  }
}

}  // namespace

void CpuBackend::gatherMediumDirect() {
  const MediumTerms m = mediumTerms(job_, dropLastLeg_);
  const capture::PrimaryRays rays(job_.imager);
  std::optional<capture::ThinLens> lens;
  if (apertureSamples_ > 1) lens.emplace(*capture::cameraOf(job_.imager));
  const int32_t width = capture::imageWidth(job_.imager);
  const std::size_t tiles = (pixelCount_ + kTilePixels - 1) / kTilePixels;
  parallelFor(tiles, threads_, [&](std::size_t tile) {
    const std::size_t end = std::min(pixelCount_, (tile + 1) * kTilePixels);
    for (std::size_t i = tile * kTilePixels; i < end; ++i) {
      const std::size_t pixel = firstPixel_ + i;
      const auto x = static_cast<int32_t>(pixel % width), y = static_cast<int32_t>(pixel / width);
      float* histogram = &direct_[i * m.bins * kChannels];
      const std::size_t first = segmentFirstSample_[i], perPixel = segmentFirstSample_[i + 1] - first;
      // Each sample's share of the pixel, as the direct gather weighs it.
      const float weight = perPixel == 1 ? 1.0f : 1.0f / static_cast<float>(perPixel);
      for (std::size_t sample = first; sample < first + perPixel; ++sample) {
        // The ray traced for the sample: its own origin (an aperture point, a
        // ray list's origin), its lens path, its surface if it met one.
        const std::size_t e = firstSample_ + sample - surfaces_->firstSample[pixel];
        const capture::ApertureRay through = ir::sampleRay(
            rays, lens ? &*lens : nullptr, x, y, surfaces_->side[pixel], apertureSamples_, e);
        const glm::vec3 origin = through.ray.origin;
        const float surface = segmentLit_[sample]
                                  ? glm::length(segmentSurfaces_[sample].x - origin)
                                  : physics::MEDIUM_UNBOUNDED;
        const physics::MediumRay ray = physics::mediumRay(
            origin, through.ray.direction, m.light, surface, m.unwarp ? 0.0f : through.lensPath_m);
        addRayLight(m, *scene_, ray, weight, histogram, outside_[i]);
      }
    }
  });
}

}  // namespace tofsim::cpu
