// The CPU backend's medium pass (issue 42, item 3): the light the medium
// filling the scene scatters once into each pixel sample's camera ray before
// its first surface (along the whole ray when it sees none), per time bin, by
// shaders/medium.glsl's quadrature; the light's visibility at each node is a
// shadow ray, as the direct gather's. Direct light (one scattering event),
// added after the surfaces' into the same histograms and off-axis sums, each
// pixel by one thread. shaders/medium_direct.comp is the GL twin; the
// physics and its accuracy: core/physics/medium_single_scattering.md. The
// bins' and nodes' walk is CpuMediumRays.h's, shared with the VPLs' pass.
#include <algorithm>
#include <optional>

#include "CpuDirectConstants.h"
#include "CpuMediumRays.h"
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

/// The medium's terms the direct gather's constants (CpuDirectConstants.h:
/// the light, its profile, the time axis, sigma_t) lack.
struct MediumTerms {
  glm::vec3 sigmaS{0.0f};
  int32_t phase = 0;
  float g = 0.0f;
};

MediumTerms mediumTerms(const capture::Medium& medium) {
  return {medium.sigma_s_per_m, medium.phase, medium.g};
}

}  // namespace

void CpuBackend::mediumSampleRays(const capture::PrimaryRays& rays, const capture::ThinLens* lens,
                                  std::size_t i, std::vector<MediumSampleRay>& out) const {
  out.clear();
  const std::size_t pixel = firstPixel_ + i;
  const int32_t width = capture::imageWidth(job_.imager);
  const auto x = static_cast<int32_t>(pixel % width), y = static_cast<int32_t>(pixel / width);
  const std::size_t first = segmentFirstSample_[i], perPixel = segmentFirstSample_[i + 1] - first;
  // Each sample's share of the pixel, as the direct gather weighs it.
  const float weight = perPixel == 1 ? 1.0f : 1.0f / static_cast<float>(perPixel);
  for (std::size_t sample = first; sample < first + perPixel; ++sample) {
    // The ray traced for the sample: its own origin (an aperture point, a
    // ray list's origin), its lens path, its surface if it met one.
    const std::size_t e = firstSample_ + sample - surfaces_->firstSample[pixel];
    const capture::ApertureRay through =
        ir::sampleRay(rays, lens, x, y, surfaces_->side[pixel], apertureSamples_, e);
    MediumSampleRay r;
    r.origin = through.ray.origin;
    r.direction = through.ray.direction;
    r.surface = segmentLit_[sample] ? glm::length(segmentSurfaces_[sample].x - r.origin)
                                    : physics::MEDIUM_UNBOUNDED;
    r.lensPath = dropLastLeg_ ? 0.0f : through.lensPath_m;
    r.weight = weight;
    out.push_back(r);
  }
}

void CpuBackend::gatherMediumDirect() {
  const DirectConstants c = directConstants();
  const MediumTerms m = mediumTerms(job_.settings.medium);
  const MediumAxis axis{c.start_m, c.width_m, c.eta, c.bins, dropLastLeg_};
  const capture::PrimaryRays rays(job_.imager);
  std::optional<capture::ThinLens> lens;
  if (apertureSamples_ > 1) lens.emplace(*capture::cameraOf(job_.imager));
  // A node's light: the light's profile toward it, a shadow ray (a medium
  // point has no surface to leave: it starts at the node), the scattering.
  const auto nodeLight = [&](const physics::MediumNode& n) {
    const float profile = physics::lightProfile(c.profile.kind, c.profile.axis, c.profile.cosOuter,
                                                c.profile.cosInner, n.fromLight);
    if (profile <= 0.0f || scene_->occluded(n.x, c.light_world)) return glm::vec3(0.0f);
    return physics::mediumNodeRadiance(n, m.sigmaS, c.sigmaT, m.phase, m.g, c.intensity_W_per_sr,
                                       profile);
  };
  const std::size_t tiles = (pixelCount_ + kTilePixels - 1) / kTilePixels;
  parallelFor(tiles, threads_, [&](std::size_t tile) {
    std::vector<MediumSampleRay> samples;
    const std::size_t end = std::min(pixelCount_, (tile + 1) * kTilePixels);
    for (std::size_t i = tile * kTilePixels; i < end; ++i) {
      mediumSampleRays(rays, lens ? &*lens : nullptr, i, samples);
      float* histogram = &direct_[i * c.bins * kChannels];
      for (const MediumSampleRay& r : samples) {
        const physics::MediumRay ray =
            physics::mediumRay(r.origin, r.direction, c.light_world, r.surface, r.lensPath);
        addMediumRayLight(axis, ray, r.weight, histogram, outside_[i], nodeLight);
      }
    }
  });
}

}  // namespace tofsim::cpu
