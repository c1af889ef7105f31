#pragma once
// Transient instant radiosity on the CPU: the IR backend interface (see
// tofsim/ir/IrBackend.h, driven by ir::IrRenderer) implemented with Embree
// rays and plain C++ loops, for machines without a GPU, where it is several
// times faster than the GL backend on Mesa's llvmpipe.
//
// The physics is the GL backend's (shaders/transient_physics.glsl, compiled as
// C++); what differs is how surfaces and visibility are found:
// - G-buffer and RSM: one ray through each pixel / texel centre instead of
//   rasterization (the same surface point up to float rounding, and at a
//   triangle edge through a centre possibly the other triangle);
// - the light's shadow test: an exact shadow ray instead of the GL's cube
//   shadow map with its depth bias, so the GL may lose light at grazing
//   angles or let it leak at contact where the CPU does not;
// - exact visibility: Embree occlusion rays instead of the GL's BVH walk,
//   between the same offset end points (the end margins differ slightly).
//
// Guarantees: every (pixel, bin) of a segment is written by one thread, which
// adds VPLs in increasing index; pixels are split into fixed tiles; so the
// bytes do not depend on the thread count or on the segment / batch plan.
// Off-axis light is summed per pixel and then over the segment in pixel order.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/util/ZeroedBuffer.h"

namespace tofsim::rays {
class RayScene;
}
namespace tofsim::capture {
class PrimaryRays;
class ThinLens;
}
namespace tofsim::physics {
struct OffAxisSums;
struct ResponseKernel;
}

namespace tofsim::cpu {

struct CpuBackendOptions {
  int threads = 0;  ///< worker threads, 0 = all cores
  /// false: every VPL sees every surface point (the gather's upper bound, for
  /// benchmarks); true: render.indirect.visibility decides.
  bool indirectVisibility = true;
};

class CpuIsm;
class LitBounds;
class ResponseClasses;
struct PixelSurface;
struct VplArrays;
struct VplTerms;
struct BlockPair;
struct MediumSampleRay;

class CpuBackend : public ir::IrBackend {
 public:
  explicit CpuBackend(const CpuBackendOptions& options = {});
  ~CpuBackend() override;

  std::string description() const override;
  ir::DeviceLimits limits() const override;
  bool tracesRays() const override { return true; }
  capture::IrCapabilities capabilities() const override { return capture::kCpuCapabilities; }
  void setScene(const scene::Scene& scene, const rays::RayScene* rays) override;
  ir::CentreSurfaces prepareSurfaces(const capture::RenderJob& job) override;
  /// Not called by the driver (the CPU backend traces every imager's samples
  /// itself): samples made otherwise (points of a medium, whose vertices
  /// have no normal: physics::VERTEX_MEDIUM), which the next prepareSurfaces
  /// gathers instead of tracing, at one sample per pixel (centres null) or
  /// with their centres.
  void setSurfaces(std::unique_ptr<ir::SurfaceImage> samples,
                   std::unique_ptr<ir::SurfaceImage> centres) override;
  void setSampledPixels(const std::vector<uint8_t>& sampled) override;
  std::vector<ir::Vpl> generateVpls(const capture::RenderJob& job) override;
  void setVpls(const std::vector<ir::Vpl>& vpls) override;
  std::size_t fixedBytes() const override;
  std::size_t visibilityBytesPerVpl() const override;
  void allocate(std::size_t pixelsPerSegment, std::size_t vplsPerBatch) override;
  void buildVisibility(std::size_t firstVpl, std::size_t count) override;
  void beginSegment(std::size_t firstPixel, std::size_t count) override;
  void gatherDirect() override;
  void gatherIndirect(std::size_t firstVpl, std::size_t count) override;
  void takeIndirect(float* indirect) override;
  void readSegment(float* direct, float* indirect, AxisLoss& offAxis) override;

  int threads() const { return threads_; }

  /// The response classes (core/physics/temporal_response.md), taken at the
  /// next allocate; the default table keeps only the instant class.
  void setResponseClasses(const physics::ResponseClassTable& classes) override;

 private:
  /// prepareSurfaces with setSurfaces' samples.
  ir::CentreSurfaces takeGivenSurfaces(const capture::RenderJob& job);
  struct DirectConstants;
  struct DirectLight;
  struct IndirectConstants;

  /// The direct light of the segment's pixels in `tile`, into direct_.
  void gatherDirectTile(std::size_t tile);
  DirectConstants directConstants() const;
  /// Segment pixel i's direct light: each lit sample's, weighted, into its bins.
  void gatherDirectPixel(const DirectConstants& c, std::size_t i);
  /// Segment sample `sample`'s unweighted direct light; false where the light
  /// does not reach it (outside its cone or shadowed). Inline (and always
  /// inlined, in CpuBackend.cpp): it runs per sample.
  inline bool directLight(const DirectConstants& c, std::size_t sample, DirectLight& out) const;
  /// The medium's single scattering along every sample's camera ray into
  /// direct_ (CpuMediumDirect.cpp): with a medium only.
  void gatherMediumDirect();
  /// The scattering regions' single scattering along every sample's camera
  /// ray into direct_ (CpuRegionDirect.cpp): with a scattering region only.
  void gatherRegionDirect();
  /// Segment pixel i's samples' camera rays, as the medium passes integrate
  /// along them (CpuMediumDirect.cpp): `rays` of the job's imager, `lens`
  /// its thin lens with aperture samples (null without).
  void mediumSampleRays(const capture::PrimaryRays& rays, const capture::ThinLens* lens,
                        std::size_t i, std::vector<MediumSampleRay>& out) const;
  /// VPLs [firstVpl, + count)'s light scattered once by the medium into
  /// every sample's camera ray (CpuMediumVpls.cpp), into mediumIndirect_:
  /// with a scattering medium only (with per-region media it hands over to
  /// gatherRegionIndirect).
  void gatherMediumIndirect(std::size_t firstVpl, std::size_t count);
  /// The same in scattering regions, along the camera rays' stretches inside
  /// them (CpuRegionVpls.cpp), into mediumIndirect_.
  void gatherRegionIndirect(std::size_t firstVpl, std::size_t count);
  /// VPLs [firstVpl, + count) into indirect_ for the segment's pixels in `tile`.
  void gatherTile(std::size_t tile, std::size_t firstVpl, std::size_t count);
  IndirectConstants indirectConstants() const;
  /// VPLs [first, + n), one block, into segment pixel i's histogram; `terms`
  /// holds a block of terms for each of the pixel's samples, `pairs` room for
  /// all of them (the visible contributions, with the footprint).
  void gatherPixelBlock(const IndirectConstants& c, std::size_t first, std::size_t n, std::size_t i,
                        VplTerms* terms, BlockPair* pairs);
  /// gatherPixelBlock's pairs with exact visibility or without the
  /// footprint: appends to `pairs` from `visible` on, or without the
  /// footprint adds each term to `histogram`.
  void visiblePairs(const IndirectConstants& c, std::size_t first, std::size_t n,
                    std::size_t perPixel, const PixelSurface* surfaces, const unsigned char* lit,
                    const VplTerms* terms, BlockPair* pairs, float* histogram,
                    physics::OffAxisSums& lost, std::size_t& visible) const;
  /// With delayed response classes, before gatherPixelBlock's deposits: each
  /// contribution of a delayed class (the VPL's class then the sample's base
  /// kernel) that is visible goes into its class's buffer, whole, and leaves
  /// `terms` (its bin set to kNoLight), so the instant light that is left
  /// goes its way of before, in the same order.
  void depositDelayedLanes(const IndirectConstants& c, std::size_t first, std::size_t n,
                           std::size_t i, std::size_t perPixel, const PixelSurface* surfaces,
                           const unsigned char* lit, VplTerms* terms);
  /// Adds pixel i's footprint buffer, if written, and its delayed classes'
  /// light to `histogram` and clears them.
  void integratePixel(std::size_t i, float* histogram);
  /// Zero the first `pixels` pixels' histograms and footprint buffers (what
  /// an unfinished segment left).
  void clearAccumulators(std::size_t pixels);
  /// Pixel i's footprint buffer, for a wide kernel's deposit (its bins
  /// join the pixel's footprintBins_).
  double* footprintOf(std::size_t i, const glm::vec3& kernel);
  /// The segment's histograms in `from` out to `to` (with the indirect
  /// light's wide footprint kernels summed in, pixel by pixel), and zeroed.
  /// `medium` (null: none): mediumIndirect_, added after the footprints and zeroed.
  void moveOut(float* from, float* to, bool integrateFootprints, float* medium = nullptr);
  /// Traces every pixel's N x N samples if adaptive samples are still waiting
  /// for a mask that did not come.
  void finishSurfaces();
  /// render.pixel_samples squared: the most samples a pixel takes.
  std::size_t maxSamplesPerPixel() const;
  /// segmentSurfaces_[i] and segmentLit_[i] from the segment's sample i, a
  /// sample of `weight` (1 / its pixel's samples) whose footprint the
  /// imager's `steps` give.
  void fillSurface(std::size_t i, float weight, const capture::PixelSteps& steps, float eta);
  /// render.indirect.merge_pixel_samples: mergedSurfaces_ and mergedFirst_
  /// from the segment's first `count` pixels' samples (cleared without it).
  void mergeSegmentSamples(std::size_t count);

  int threads_ = 1;
  bool indirectVisibility_ = true;
  capture::RenderJob job_;
  /// job_'s per-region media joined with their meshes (empty: none).
  capture::MediumRegions regions_;
  /// The last leg is not timed: render.camera_unwarp, or an imager whose
  /// last leg does not count (capture::lastLegCounts).
  bool dropLastLeg_ = false;
  const rays::RayScene* scene_ = nullptr;  ///< the driver's (setScene)
  std::unique_ptr<LitBounds> litBounds_;   ///< of the scene set (setScene)
  std::unique_ptr<ir::SurfaceImage>
      surfaces_;  ///< every pixel's samples (SurfaceImage::firstSample)
  /// render.adaptive_pixel_samples: surfaces_ holds the centres until
  /// setSampledPixels (or finishSurfaces) traces the sub-samples.
  bool subSamplesPending_ = false;
  std::unique_ptr<ir::SurfaceImage> givenSamples_, givenCentres_;  ///< setSurfaces', until used
  int32_t apertureSamples_ = 1;  ///< per pixel sample (capture::apertureSamplesOf)
  std::unique_ptr<VplArrays> vpls_;
  std::unique_ptr<CpuIsm> ism_;
  std::vector<PixelSurface> segmentSurfaces_;  ///< per sample of the segment's pixels
  std::vector<unsigned char> segmentLit_;      ///< 1 where the sample sees a surface
  /// Segment pixel i's samples are [segmentFirstSample_[i], [i + 1]) of the
  /// two above, surfaces_ entries from firstSample_ on.
  std::vector<std::size_t> segmentFirstSample_;
  /// render.indirect.merge_pixel_samples: the indirect gather's samples, a
  /// pixel's merged per flat surface (MergedSamples.h), pixel i's
  /// [mergedFirst_[i], [i + 1]); empty without merging (the gather reads the
  /// samples above).
  std::vector<PixelSurface> mergedSurfaces_;
  std::vector<std::size_t> mergedFirst_;
  std::size_t firstSample_ = 0;
  /// The segment's histograms, (pixel, bin, channel); zero from the kernel
  /// (ZeroedBuffer.h) and kept across renders of the same size.
  util::ZeroedBuffer<float> direct_, indirect_;
  /// With a scattering medium and VPLs (mediumVpls_): the VPLs' light the
  /// medium scatters into the camera rays, (pixel, bin, channel) and off
  /// the axis, kept apart from indirect_ so that each (pixel, bin) adds it in
  /// VPL order whatever the batch plan; moveOut adds it to the indirect light.
  util::ZeroedBuffer<float> mediumIndirect_;
  std::vector<physics::OffAxisSums> mediumOutside_;
  bool mediumVpls_ = false;
  /// The (ray, VPL) pairs' roulette threshold (ir::mediumRayThreshold).
  float mediumRayThreshold_ = 0.0f;
  /// render.indirect.gather_pairs: each VPL's importance for the surface
  /// gather's roulette (GatherRoulette.h); empty: every pair gathered.
  std::vector<float> gatherImportance_;
  /// direct_, indirect_ and footprint_ hold zeros (after allocate and readSegment).
  bool accumulatorsZero_ = false;
  std::vector<physics::OffAxisSums> outside_;  ///< per pixel of the segment: light off the axis
  /// The pixel footprint's difference buffers (bins x 3 doubles per pixel of
  /// the segment) and the bins of each that the wide kernels may have
  /// written, [first, last] (none when first > last). Zero elsewhere:
  /// integratePixel sums from `first` on (the entries before are zero, so
  /// are the sums: the same bytes) and zeroes what was written, while in
  /// cache, so pixels without a wide kernel never touch their pages.
  util::ZeroedBuffer<double> footprint_;
  struct FootprintBins {
    int32_t first = INT32_MAX;
    int32_t last = -1;
  };
  std::vector<FootprintBins> footprintBins_;
  /// The delayed classes' kernels and buffers (empty: none), integrated into
  /// a pixel's histogram by integratePixel.
  physics::ResponseClassTable responseClasses_;  ///< setResponseClasses'
  std::unique_ptr<ResponseClasses> responses_;
  std::size_t firstPixel_ = 0, pixelCount_ = 0, pixelsPerSegment_ = 0;
  float sceneScale_m_ = 1.0f;
};

}  // namespace tofsim::cpu
