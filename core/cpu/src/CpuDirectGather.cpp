// The CPU backend's direct gather: each pixel sample's light straight from
// the light source (a shadow ray, the light's profile, the BRDF and the
// footprint), per tile of pixels. The rest of the backend: CpuBackend.cpp.
#include <algorithm>
#include <cmath>

#include "CpuDirectConstants.h"
#include "GatherKernel.h"
#include "GatherTiles.h"
#include "ParallelFor.h"
#include "ResponseClasses.h"
#include "tofsim/capture/ThinLens.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/physics/FootprintBuffer.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/physics/ScatterVertex.h"
#include "tofsim/physics/TransientPhysics.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/util/Error.h"

namespace tofsim::cpu {

void CpuBackend::gatherDirect() {
  const std::size_t tiles = (pixelCount_ + kTilePixels - 1) / kTilePixels;
  parallelFor(tiles, threads_, [&](std::size_t tile) { gatherDirectTile(tile); });
  // An absorbing medium scatters nothing into the rays (it only attenuates).
  if (job_.settings.medium.scatters()) gatherMediumDirect();
  if (regions_.scatters()) gatherRegionDirect();
}

/// One sample's direct light, before its share of the pixel.
struct CpuBackend::DirectLight {
  glm::vec3 radiance{0.0f};
  float path_m = 0.0f;  ///< optical path light -> x (-> viewpoint)
};

CpuBackend::DirectConstants CpuBackend::directConstants() const {
  const capture::RenderSettings& s = job_.settings;
  DirectConstants c;
  c.profile = job_.light.profileTerms();
  c.light_world = job_.light.position_world;
  c.intensity_W_per_sr = job_.light.intensity_W_per_sr;
  c.start_m = static_cast<float>(s.time.start_m());
  c.width_m = static_cast<float>(s.time.bin_width_m());
  c.eta = static_cast<float>(s.time.index_of_refraction);
  c.bins = s.time.bins;
  c.footprint = s.pixel_footprint;
  c.delayed = !responses_->empty();
  c.medium = s.medium.present();
  c.sigmaT = s.medium.sigmaT();
  return c;
}

// Called per sample: always inlined, so that the split leaves the hot
// loop as it was (no call per sample).
[[gnu::always_inline]] inline bool CpuBackend::directLight(const DirectConstants& c,
                                                           std::size_t sample,
                                                           DirectLight& out) const {
  const std::size_t p = firstSample_ + sample;
  const PixelSurface& surface = segmentSurfaces_[sample];
  const glm::vec3 x = surface.x, n = surface.n;
  // direct_gather.comp's steps: how the light arrives (shared), whether
  // it is visible (here a ray, there the shadow map), what x reflects.
  const physics::LightArrival arrival =
      physics::vertexLightArrival(surface.vertex, x, n, c.light_world, c.profile.kind,
                                  c.profile.axis, c.profile.cosOuter, c.profile.cosInner);
  const float profile = arrival.profile, cosX = arrival.cosX, dLight = arrival.dLight;
  const glm::vec3 wLight = arrival.wLight;
  if (profile <= 0.0f) return false;
  const glm::vec3 toLight = c.light_world - x;
  const glm::vec3 g = surfaces_->geometric[p];
  const glm::vec3 offset = (glm::dot(g, toLight) < 0.0f ? -g : g) * scene_->epsilon_m();
  if (scene_->occluded(x + offset, c.light_world)) return false;
  const glm::vec3 f = physics::scatter(surface.vertex, n, wLight, surface.toCamera).f;
  out.radiance = physics::directRadiance(f, c.intensity_W_per_sr, profile, cosX, dLight);
  // A medium: the light -> x and x -> camera legs (the latter whatever the unwarp).
  if (c.medium) {
    out.radiance *= physics::mediumTransmittance(c.sigmaT, dLight + surface.cameraLeg_m);
  }
  float dCamera = dropLastLeg_ ? 0.0f : glm::length(x - surface.camera) + surface.lensPath_m;
  if (!regions_.empty()) {  // the light and camera legs through the media's regions
    const capture::RegionPassage leg = regions_.passage(glm::dvec3(c.light_world), glm::dvec3(x));
    out.radiance *= glm::vec3(leg.transmittance()) * surface.regionCameraT;
    if (!dropLastLeg_) dCamera += surface.regionCameraExtra_m;
    out.path_m =
        physics::directPathLength(c.eta, dLight + static_cast<float>(leg.extraPath_m), dCamera);
    return true;
  }
  out.path_m = physics::directPathLength(c.eta, dLight, dCamera);
  return true;
}

void CpuBackend::gatherDirectTile(std::size_t tile) {
  const DirectConstants c = directConstants();
  const std::size_t end = std::min(pixelCount_, (tile + 1) * kTilePixels);
  for (std::size_t i = tile * kTilePixels; i < end; ++i) gatherDirectPixel(c, i);
}

void CpuBackend::gatherDirectPixel(const DirectConstants& c, std::size_t i) {
  float* histogram = &direct_[i * c.bins * kChannels];
  physics::OffAxisSums& lost = outside_[i];
  const std::size_t perPixel = segmentFirstSample_[i + 1] - segmentFirstSample_[i];
  const float weight = 1.0f / static_cast<float>(perPixel);
  for (std::size_t sample = segmentFirstSample_[i]; sample < segmentFirstSample_[i + 1]; ++sample) {
    if (!segmentLit_[sample]) continue;
    DirectLight light;
    if (!directLight(c, sample, light)) continue;
    // The sample's own surface is the path's only delayed vertex.
    const uint32_t cls =
        c.delayed ? responseClasses_.single(
                        static_cast<uint32_t>(segmentSurfaces_[sample].vertex.response))
                  : 0u;
    if (c.footprint) {
      const PixelSurface& surface = segmentSurfaces_[sample];
      const glm::vec2 steps = physics::pathStepsAcrossPixel(
          physics::opticalPathGradient(surface.x, c.light_world, surface.camera, c.eta,
                                       dropLastLeg_),
          surface.dxdu, surface.dxdv);
      const glm::vec3 kernel = physics::footprintKernel(light.path_m, steps, c.start_m, c.width_m);
      const glm::vec3 value = light.radiance * weight;
      if (cls != 0) {
        responses_->deposit(i, cls, kernel, value, lost);
      } else if (physics::footprintIsNarrow(kernel)) {
        physics::depositNarrow(histogram, c.bins, kernel, value, lost);
      } else {
        physics::depositWide(footprintOf(i, kernel), c.bins, kernel, value, lost);
      }
      continue;
    }
    // Point sampling (render.pixel_footprint: false): the bytes of before
    // the footprint existed when there is one sample.
    const glm::vec3 value = perPixel == 1 ? light.radiance : light.radiance * weight;
    const int bin = physics::binOfPath(light.path_m, c.start_m, c.width_m);
    if (cls != 0) {
      responses_->depositInBin(i, cls, bin, value, lost);
      continue;
    }
    physics::depositInBin(histogram, c.bins, bin, 1.0f, value, lost);
  }
  // The footprint buffer and the delayed classes are the indirect gathers' next.
  if (c.footprint || c.delayed) integratePixel(i, histogram);
}

}  // namespace tofsim::cpu
