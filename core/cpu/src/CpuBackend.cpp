#include "tofsim/cpu/CpuBackend.h"

#include <algorithm>
#include <cmath>
#include <thread>
#include <utility>

#include "CpuIsm.h"
#include "FootprintDeposit.h"
#include "GatherKernel.h"
#include "GatherRoulette.h"
#include "GatherTiles.h"
#include "LitBounds.h"
#include "MergedSamples.h"
#include "ParallelFor.h"
#include "ResponseClasses.h"
#include "RsmVpls.h"
#include "VplArrays.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/capture/ThinLens.h"
#include "tofsim/ir/MediumRayVpls.h"
#include "tofsim/ir/MediumVpl.h"
#include "tofsim/ir/RsmTexels.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/physics/FootprintBuffer.h"
#include "tofsim/physics/ScatterVertex.h"
#include "tofsim/physics/TemporalResponse.h"
#include "tofsim/physics/TransientPhysics.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/util/Error.h"

namespace tofsim::cpu {

namespace {

// Exact visibility (render.indirect.visibility: exact): whether the ray from
// VPL `vpl`, lifted off its surface by eps, to sample `surface` (lifted
// likewise) is blocked; eps as indirect_gather.comp's.
inline bool vplOccluded(const rays::RayScene& scene, const VplArrays& v, std::size_t vpl,
                        const PixelSurface& surface, float eps) {
  const glm::vec3 from = glm::vec3(v.px[vpl], v.py[vpl], v.pz[vpl]) +
                         glm::vec3(v.nx[vpl], v.ny[vpl], v.nz[vpl]) * eps;
  return scene.occluded(from, surface.x + surface.n * eps);
}

// ISM visibility with medium VPLs: a medium VPL has no hemisphere about a
// normal to map (its map stays empty and passes every lane), so its lanes
// lit by the block are tested by exact rays here.
void cullOccludedMediumLanes(const rays::RayScene& scene, const VplArrays& v, std::size_t first,
                             std::size_t n, const PixelSurface& surface, float eps,
                             VplTerms& terms) {
  for (std::size_t k = 0; k < n; ++k) {
    if (terms.bin[k] == kNoLight || v.emitterOffset[first + k] == 0.0f) continue;
    if (vplOccluded(scene, v, first + k, surface, eps)) terms.bin[k] = kNoLight;
  }
}

}  // namespace

using ir::SurfaceImage;
using ir::traceSampledPixels;
using ir::traceSurfaces;

CpuBackend::CpuBackend(const CpuBackendOptions& options)
    : threads_(resolveThreads(options.threads)),
      indirectVisibility_(options.indirectVisibility),
      responses_(std::make_unique<ResponseClasses>()) {}

CpuBackend::~CpuBackend() = default;

std::string CpuBackend::description() const {
  return "CPU (" + std::to_string(threads_) + (threads_ == 1 ? " thread" : " threads") +
         ", Embree)";
}

ir::DeviceLimits CpuBackend::limits() const {
  // Only memory bounds the CPU; these keep index arithmetic far from overflow.
  return {1 << 16, std::size_t{1} << 40, std::size_t{1} << 32};
}

void CpuBackend::setScene(const scene::Scene& scene, const rays::RayScene* rays) {
  TOFSIM_CHECK_MSG(rays != nullptr, "the CPU backend traces the driver's RayScene");
  scene_ = rays;
  litBounds_ = std::make_unique<LitBounds>(scene);
  const scene::Bounds b = scene.bounds();
  sceneScale_m_ = std::max(glm::length(b.max - b.min), 1e-6f);
}

ir::CentreSurfaces CpuBackend::prepareSurfaces(const capture::RenderJob& job) {
  TOFSIM_CHECK(job.scene != nullptr);
  TOFSIM_CHECK_MSG(scene_ != nullptr, "setScene must come first");
  job_ = job;
  regions_ = capture::MediumRegions(job.settings.media, *job.scene,
                                    job.settings.time.index_of_refraction);
  dropLastLeg_ = job.settings.time.camera_unwarp || !capture::lastLegCounts(job.imager);
  vpls_.reset();  // a new render: nothing of the previous one survives
  mediumVpls_ = false;
  ism_.reset();
  // The driver's G-buffer (depth, the light seen by the camera, the adaptive
  // samples' edges) is the pixel centres', whatever the sub-pixel samples.
  // With adaptive samples the sub-samples wait for the driver's mask
  // (setSampledPixels), so only the edge pixels' rays are traced.
  // A defocused camera's centres are its chief rays (the aperture's centre),
  // every gathered sample one of its aperture points'.
  if (givenSamples_) return takeGivenSurfaces(job);
  const int32_t samples = job.settings.pixel_samples;
  apertureSamples_ = capture::apertureSamplesOf(job.imager);
  const int model = ir::vertexModelOf(job.settings.materials);
  SurfaceImage centres = traceSurfaces(*scene_, job.imager, threads_, 1, 1, model);
  ir::CentreSurfaces out = ir::centresOf(centres);
  subSamplesPending_ = samples > 1 && job.settings.adaptive_pixel_samples;
  if (subSamplesPending_ || (samples == 1 && apertureSamples_ == 1)) {
    surfaces_ = std::make_unique<SurfaceImage>(std::move(centres));
  } else {
    surfaces_ = std::make_unique<SurfaceImage>(
        traceSurfaces(*scene_, job.imager, threads_, samples, apertureSamples_, model));
  }
  return out;
}

void CpuBackend::setSurfaces(std::unique_ptr<SurfaceImage> samples,
                             std::unique_ptr<SurfaceImage> centres) {
  TOFSIM_CHECK(samples != nullptr);
  givenSamples_ = std::move(samples);
  givenCentres_ = std::move(centres);
}

ir::CentreSurfaces CpuBackend::takeGivenSurfaces(const capture::RenderJob& job) {
  TOFSIM_CHECK_MSG(!(job.settings.pixel_samples > 1 && job.settings.adaptive_pixel_samples),
                   "given samples take no adaptive pixel samples");
  TOFSIM_CHECK_EQ(givenSamples_->apertureSamples, 1);
  apertureSamples_ = 1;
  subSamplesPending_ = false;
  ir::CentreSurfaces out = ir::centresOf(givenCentres_ ? *givenCentres_ : *givenSamples_);
  surfaces_ = std::move(givenSamples_);
  givenCentres_.reset();
  return out;
}

void CpuBackend::setSampledPixels(const std::vector<uint8_t>& sampled) {
  TOFSIM_CHECK_MSG(subSamplesPending_,
                   "setSampledPixels needs adaptive_pixel_samples with pixel_samples > 1");
  surfaces_ = std::make_unique<SurfaceImage>(
      traceSampledPixels(*scene_, job_.imager, threads_, job_.settings.pixel_samples, sampled,
                         apertureSamples_, ir::vertexModelOf(job_.settings.materials)));
  subSamplesPending_ = false;
}

void CpuBackend::finishSurfaces() {
  // No mask came (IrBackend: every pixel then takes its N x N samples).
  if (!subSamplesPending_) return;
  surfaces_ = std::make_unique<SurfaceImage>(
      traceSurfaces(*scene_, job_.imager, threads_, job_.settings.pixel_samples, apertureSamples_,
                    ir::vertexModelOf(job_.settings.materials)));
  subSamplesPending_ = false;
}

std::size_t CpuBackend::maxSamplesPerPixel() const {
  const auto n = static_cast<std::size_t>(job_.settings.pixel_samples);
  return n * n * static_cast<std::size_t>(apertureSamples_);
}

std::vector<ir::Vpl> CpuBackend::generateVpls(const capture::RenderJob& job) {
  TOFSIM_CHECK(scene_ != nullptr);  // prepareSurfaces comes first
  finishSurfaces();
  const capture::IndirectSettings& s = job.settings.indirect;
  if (!s.enabled) return {};
  std::vector<ir::Vpl> vpls = traceRsmVpls(
      *scene_, job.light, s.rsm_resolution, s.rsm_edge_samples,
      job.settings.time.index_of_refraction, ir::vertexModelOf(job.settings.materials), threads_,
      litBounds_->of(job.light), &responseClasses_, job.settings.medium);
  ir::attenuateLightLegs(vpls, regions_, job.light.position_world,
                         job.settings.time.index_of_refraction);
  return vpls;
}

void CpuBackend::setVpls(const std::vector<ir::Vpl>& vpls) {
  vpls_ = std::make_unique<VplArrays>(vpls);
  mediumVpls_ = !vpls.empty() && ir::vplsLightCameraRays(job_.settings);
  mediumRayThreshold_ = ir::mediumRayThreshold(vpls, sceneScale_m_);
  gatherImportance_.clear();
  if (job_.settings.indirect.gather_pairs > 0) gatherImportance_ = gatherImportance(*vpls_);
  ism_.reset();
  if (indirectVisibility_ && job_.settings.indirect.visibility == capture::Visibility::Ism &&
      !vpls.empty()) {
    ism_ = std::make_unique<CpuIsm>(*job_.scene, vpls, job_.settings.indirect, job_.settings.seed);
  }
}

std::size_t CpuBackend::fixedBytes() const {
  std::size_t bytes =
      surfaces_ ? surfaces_->size() * (2 * sizeof(glm::vec4) + sizeof(physics::ScatterVertex) +
                                       sizeof(glm::vec3)) +
                      surfaces_->aperture.size() * sizeof(glm::vec4)
                : 0;
  // Embree's BVH and vertex copies: about 100 bytes per triangle (measured order).
  if (job_.scene != nullptr) bytes += job_.scene->triangleCount() * 100;
  if (vpls_) bytes += vpls_->bytes();
  if (ism_) bytes += ism_->fixedBytes();
  return bytes;
}

std::size_t CpuBackend::visibilityBytesPerVpl() const { return ism_ ? ism_->bytesPerVpl() : 0; }

void CpuBackend::buildVisibility(std::size_t firstVpl, std::size_t count) {
  if (ism_) ism_->build(firstVpl, count, threads_);
}

void CpuBackend::beginSegment(std::size_t firstPixel, std::size_t count) {
  TOFSIM_CHECK(count <= pixelsPerSegment_);
  firstPixel_ = firstPixel;
  pixelCount_ = count;
  // readSegment leaves the histograms zero (it zeroes each pixel's as it
  // copies it out, while it is in cache): a second pass over the segment's
  // memory only after an unfinished one.
  if (!accumulatorsZero_) clearAccumulators(pixelsPerSegment_);
  accumulatorsZero_ = false;
  std::fill_n(outside_.begin(), count, physics::OffAxisSums{});
  const capture::RenderSettings& s = job_.settings;
  const auto eta = static_cast<float>(s.time.index_of_refraction);
  firstSample_ = surfaces_->firstSample[firstPixel];
  for (std::size_t i = 0; i <= count; ++i) {
    segmentFirstSample_[i] = surfaces_->firstSample[firstPixel + i] - firstSample_;
  }
  for (std::size_t pixel = 0; pixel < count; ++pixel) {
    // Each of a pixel's N x N (x K aperture points) samples stands for 1 /
    // (N^2 K) of it and its footprint is its sub-pixel: the ray steps shrink
    // by N (N = 1: the pixel-centre sample of pixel_samples: 1, the same
    // float operations).
    const int32_t n = surfaces_->side[firstPixel + pixel];
    const float weight = 1.0f / static_cast<float>(static_cast<std::size_t>(n) * n *
                                                   static_cast<std::size_t>(apertureSamples_));
    const std::size_t p = firstPixel + pixel;
    const auto width = static_cast<std::size_t>(capture::imageWidth(job_.imager));
    const capture::PixelSteps steps(job_.imager, 1.0f / static_cast<float>(n),
                                    static_cast<int32_t>(p % width),
                                    static_cast<int32_t>(p / width));
    for (std::size_t i = segmentFirstSample_[pixel]; i < segmentFirstSample_[pixel + 1]; ++i) {
      fillSurface(i, weight, steps, eta);
    }
  }
  if (!gatherImportance_.empty()) {  // render.indirect.gather_pairs
    setGatherThresholds(segmentSurfaces_.data(), segmentLit_.data(), segmentFirstSample_[count],
                        firstSample_, *vpls_, gatherImportance_.data(),
                        s.indirect.gather_pairs, threads_);
  }
  mergeSegmentSamples(count);
}

void CpuBackend::mergeSegmentSamples(std::size_t count) {
  mergedSurfaces_.clear();
  mergedFirst_.clear();
  const capture::RenderSettings& s = job_.settings;
  // Not with aperture samples (they see through different points of the
  // lens).
  if (!s.indirect.merge_pixel_samples || s.pixel_samples == 1 || apertureSamples_ != 1) return;
  mergedFirst_.push_back(0);
  for (std::size_t pixel = 0; pixel < count; ++pixel) {
    const std::size_t first = segmentFirstSample_[pixel];
    const std::size_t samples = segmentFirstSample_[pixel + 1] - first;
    const int n = surfaces_->side[firstPixel_ + pixel];
    TOFSIM_CHECK_EQ(samples, static_cast<std::size_t>(n) * n);
    // Only where every scatter is constant: a glTF BRDF's does not add up as
    // albedos do. The others' lit samples stay as they are, in order.
    // Nor where a sample is a medium point: it has no plane to be flat in.
    bool constant = true;
    for (std::size_t i = first; i < first + samples; ++i) {
      const physics::ScatterVertex& vertex = segmentSurfaces_[i].vertex;
      constant = constant && physics::scatterIsConstant(vertex) && physics::vertexOnSurface(vertex) &&
                 vertex.response == segmentSurfaces_[first].vertex.response;
    }
    if (constant) {
      mergePixelSamples(&segmentSurfaces_[first], &segmentLit_[first], n, mergedSurfaces_);
    } else {
      for (std::size_t i = first; i < first + samples; ++i) {
        if (segmentLit_[i]) mergedSurfaces_.push_back(segmentSurfaces_[i]);
      }
    }
    mergedFirst_.push_back(mergedSurfaces_.size());
  }
}

void CpuBackend::fillSurface(std::size_t i, float weight, const capture::PixelSteps& steps,
                             float eta) {
  const std::size_t p = firstSample_ + i;
  // The camera leg ends on the sample's aperture point (the viewpoint without
  // one), where the lens's path to the pixel starts.
  const glm::vec3 viewpoint = surfaces_->cameraOf(p, capture::viewpoint(job_.imager));
  segmentLit_[i] = surfaces_->position[p].w != 0.0f;
  PixelSurface& surface = segmentSurfaces_[i];
  surface.x = glm::vec3(surfaces_->position[p]);
  surface.camera = viewpoint;
  surface.lensPath_m = surfaces_->lensPathOf(p);
  surface.vertex = surfaces_->vertex[p];
  surface.n = physics::receiverNormal(surface.vertex, glm::vec3(surfaces_->normal[p]));
  surface.cosineOffset = physics::receiverCosineOffset(surface.vertex);
  surface.toCamera = glm::normalize(viewpoint - surface.x);
  surface.weight = weight;
  // The constant scatter's f (the directions do not matter to it).
  surface.brdf =
      physics::scatter(surface.vertex, surface.n, surface.toCamera, surface.toCamera).f * weight;
  surface.cameraLeg_m = glm::length(surface.x - viewpoint);
  surface.cameraPath_m = physics::cameraPathLength(
      dropLastLeg_, eta, glm::length(surface.x - viewpoint) + surface.lensPath_m);
  if (!regions_.empty()) {  // the camera leg through the media's regions
    const capture::RegionPassage leg = regions_.passage(glm::dvec3(surface.x), glm::dvec3(viewpoint));
    surface.regionCameraT = glm::vec3(leg.transmittance());
    surface.regionCameraExtra_m = static_cast<float>(leg.extraPath_m);
    surface.cameraPath_m = physics::cameraPathLength(
        dropLastLeg_, eta,
        glm::length(surface.x - viewpoint) + surface.lensPath_m + surface.regionCameraExtra_m);
  }
  // On a surface its tangent plane; at a medium point the ray's cross-section.
  const capture::FootprintSteps footprint = steps.at(
      surface.x, physics::footprintPlaneNormal(surface.vertex, surface.n, -surface.toCamera),
      viewpoint);
  surface.dxdu = footprint.dxdu;
  surface.dxdv = footprint.dxdv;
}

void CpuBackend::gatherIndirect(std::size_t firstVpl, std::size_t count) {
  TOFSIM_CHECK(vpls_ != nullptr && firstVpl + count <= vpls_->count);
  const std::size_t tiles = (pixelCount_ + kTilePixels - 1) / kTilePixels;
  parallelFor(tiles, threads_, [&](std::size_t tile) { gatherTile(tile, firstVpl, count); });
  if (mediumVpls_) gatherMediumIndirect(firstVpl, count);
}

/// What the job fixes for every indirect contribution of a tile.
struct CpuBackend::IndirectConstants {
  GatherConstants kernel;  ///< vplTerms'
  bool exact = false;      ///< render.indirect.visibility: exact, an occlusion ray each
  float eps = 0.0f;        ///< the exact visibility rays' end offsets, m
  bool delayed = false;    ///< the render has delayed response classes
};

CpuBackend::IndirectConstants CpuBackend::indirectConstants() const {
  const capture::RenderSettings& s = job_.settings;
  IndirectConstants ic;
  GatherConstants& c = ic.kernel;
  c.start_m = static_cast<float>(s.time.start_m());
  c.binWidth_m = static_cast<float>(s.time.bin_width_m());
  c.indexOfRefraction = static_cast<float>(s.time.index_of_refraction);
  c.geometryClamp = static_cast<float>(s.indirect.geometry_term_clamp_per_m2);
  c.footprint = s.pixel_footprint;
  c.vplFootprint = s.pixel_footprint && s.indirect.vpl_footprint;
  c.cameraUnwarp = dropLastLeg_;
  c.vplBrdfClamp = static_cast<float>(s.indirect.vpl_brdf_clamp_per_sr);
  c.bins = s.time.bins;
  c.medium = s.medium.present();
  c.sigmaT = s.medium.sigmaT();
  c.regions = regions_.empty() ? nullptr : &regions_;
  c.rouletteImportance = gatherImportance_.empty() ? nullptr : gatherImportance_.data();
  c.rouletteSeed = gatherRouletteSeed(s.seed);
  ic.exact = indirectVisibility_ && s.indirect.visibility == capture::Visibility::Exact;
  ic.eps = 1e-4f * sceneScale_m_;  // as indirect_gather.comp's exact visibility
  ic.delayed = !responses_->empty();
  return ic;
}

void CpuBackend::gatherTile(std::size_t tile, std::size_t firstVpl, std::size_t count) {
  const IndirectConstants c = indirectConstants();
  // One block of terms per sample: contributions are added VPL by VPL and,
  // for each VPL, sample by sample, so the order of the additions (and the
  // bytes) does not depend on where the blocks and batches start.
  std::vector<VplTerms> terms(maxSamplesPerPixel());
  // With the footprint, each pixel block's visible contributions, in order.
  std::vector<BlockPair> pairs(c.kernel.footprint ? terms.size() * kVplBlock : 0);
  const std::size_t end = std::min(pixelCount_, (tile + 1) * kTilePixels);
  for (std::size_t first = firstVpl; first < firstVpl + count; first += kVplBlock) {
    const std::size_t n = std::min(kVplBlock, firstVpl + count - first);
    for (std::size_t i = tile * kTilePixels; i < end; ++i) {
      gatherPixelBlock(c, first, n, i, terms.data(), pairs.data());
    }
  }
}

void CpuBackend::gatherPixelBlock(const IndirectConstants& c, std::size_t first, std::size_t n,
                                  std::size_t i, VplTerms* terms, BlockPair* pairs) {
  const int bins = c.kernel.bins;
  const bool exact = c.exact, footprint = c.kernel.footprint;
  const VplArrays& v = *vpls_;
  float* histogram = &indirect_[i * bins * kChannels];
  physics::OffAxisSums& lost = outside_[i];
  // The pixel's samples, or with merge_pixel_samples its merged ones (all
  // lit: `lit` null).
  const bool merged = !mergedFirst_.empty();
  const std::size_t firstOfPixel = merged ? mergedFirst_[i] : segmentFirstSample_[i];
  const std::size_t perPixel =
      (merged ? mergedFirst_[i + 1] : segmentFirstSample_[i + 1]) - firstOfPixel;
  const PixelSurface* surfaces =
      (merged ? mergedSurfaces_.data() : segmentSurfaces_.data()) + firstOfPixel;
  const unsigned char* lit = merged ? nullptr : segmentLit_.data() + firstOfPixel;
  // With ISMs the maps' verdicts come with the terms, a block at a time.
  const CpuIsm* ism = exact ? nullptr : ism_.get();
  for (std::size_t s = 0; s < perPixel; ++s) {
    if (lit && !lit[s]) continue;
    vplTerms(surfaces[s], v, first, n, c.kernel, terms[s]);
    if (ism) {
      ism->cullHidden(first, n, sceneScale_m_, surfaces[s].n, surfaces[s].cosineOffset, terms[s]);
      if (v.anyMedium) cullOccludedMediumLanes(*scene_, v, first, n, surfaces[s], c.eps, terms[s]);
    }
  }
  if (c.delayed) depositDelayedLanes(c, first, n, i, perPixel, surfaces, lit, terms);
  std::size_t visible = 0;  // contributions in `pairs`
  if (footprint && !exact) {
    // ISMs or no visibility: the verdicts are in the bins already, so the
    // lit lanes go in order without a branch per lane (each is written, the
    // count moves past the lit ones).
    for (std::size_t k = 0; k < n; ++k) {
      for (std::size_t s = 0; s < perPixel; ++s) {
        if (lit && !lit[s]) continue;
        pairs[visible] = {static_cast<uint32_t>(s), static_cast<uint32_t>(k)};
        visible += terms[s].bin[k] != kNoLight;
      }
    }
  } else {
    visiblePairs(c, first, n, perPixel, surfaces, lit, terms, pairs, histogram, lost, visible);
  }
  // The visible contributions through their footprint kernels, in the order
  // above: narrow ones into the histogram, wide ones into the pixel's
  // difference buffer.
  if (visible > 0) {
    const std::size_t stride = static_cast<std::size_t>(bins) * kChannels;
    depositFootprints(terms, pairs, visible, bins, histogram, footprint_.data() + i * stride, lost,
                      footprintBins_[i].first, footprintBins_[i].last);
  }
}

// Out of line: the instant renders' gather keeps the code it had.
[[gnu::noinline]] void CpuBackend::depositDelayedLanes(const IndirectConstants& c,
                                                       std::size_t first, std::size_t n,
                                                       std::size_t i, std::size_t perPixel,
                                                       const PixelSurface* surfaces,
                                                       const unsigned char* lit, VplTerms* terms) {
  const VplArrays& v = *vpls_;
  const physics::ResponseClassTable& table = responseClasses_;
  physics::OffAxisSums& lost = outside_[i];
  // VPL by VPL and, for each, sample by sample: the order of the instant
  // light's deposits, so each class's sums are in a fixed order too.
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t vpl = first + k;
    const uint32_t from = v.responseClass.empty() ? 0u : v.responseClass[vpl];
    for (std::size_t s = 0; s < perPixel; ++s) {
      if (lit && !lit[s]) continue;
      VplTerms& t = terms[s];
      if (t.bin[k] == kNoLight) continue;
      const PixelSurface& surface = surfaces[s];
      const uint32_t cls = table.then(from, static_cast<uint32_t>(surface.vertex.response));
      if (cls == 0) continue;
      TOFSIM_CHECK(cls != physics::ResponseClassTable::kNoClass);
      const int32_t bin = t.bin[k];
      t.bin[k] = kNoLight;  // the instant passes skip it
      if (c.exact && vplOccluded(*scene_, v, vpl, surface, c.eps)) continue;
      const glm::vec3 energy(t.r[k], t.g[k], t.b[k]);
      if (c.kernel.footprint) {
        responses_->deposit(i, cls, glm::vec3(t.centre[k], t.wide[k], t.narrow[k]), energy, lost);
      } else {
        responses_->depositInBin(i, cls, bin, energy, lost);
      }
    }
  }
}

// gatherPixelBlock with exact visibility or without the footprint: VPL by
// VPL and, for each, sample by sample, the exact visibility rays' verdicts;
// with the footprint the visible pairs into `pairs`, without it each term
// into its bin.
void CpuBackend::visiblePairs(const IndirectConstants& c, std::size_t first, std::size_t n,
                              std::size_t perPixel, const PixelSurface* surfaces,
                              const unsigned char* lit, const VplTerms* terms, BlockPair* pairs,
                              float* histogram, physics::OffAxisSums& lost,
                              std::size_t& visible) const {
  // Locals, not reads through `c`, in the loop: the histogram's float stores
  // could otherwise alias them.
  const int bins = c.kernel.bins;
  const bool exact = c.exact, footprint = c.kernel.footprint;
  const float eps = c.eps;
  const VplArrays& v = *vpls_;
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t s = 0; s < perPixel; ++s) {
      if (lit && !lit[s]) continue;
      const VplTerms& t = terms[s];
      const int32_t bin = t.bin[k];
      if (bin == kNoLight) continue;
      const PixelSurface& surface = surfaces[s];
      const std::size_t vpl = first + k;
      if (exact && vplOccluded(*scene_, v, vpl, surface, eps)) continue;
      if (footprint) {
        pairs[visible++] = {static_cast<uint32_t>(s), static_cast<uint32_t>(k)};
        continue;
      }
      physics::depositInBin(histogram, bins, bin, 1.0f, glm::vec3(t.r[k], t.g[k], t.b[k]), lost);
    }
  }
}

}  // namespace tofsim::cpu
