// render.adaptive_pixel_samples on the GL backend, through the IR driver on
// the Cornell box: with a mask set by hand (in place of the driver's edge
// pixels), every masked-out pixel's direct and indirect volume is the same
// pixel's of a render.pixel_samples: 1 render, and every other pixel's that of
// the pixel_samples N render, bit for bit: a masked-out pixel runs the
// arithmetic of one sample per pixel (centre G-buffer, weight 1, the whole
// pixel's footprint steps) and a masked-in one that of N x N, in the same
// order of additions. An all-ones mask gives the non-adaptive N render's
// bytes. The driver's own mask (its edge pixels) the same way. Needs a GL
// context (llvmpipe in CI).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>

#include "support/BackendScene.h"
#include "support/GlTestContext.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/ir/LitPixels.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/util/Error.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/render/GlBackend.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::render {
namespace {

// The GL backend with the driver's mask replaced by `mask`: every call goes
// to the real backend unchanged but setSampledPixels.
class HandMaskedBackend : public ir::IrBackend {
 public:
  explicit HandMaskedBackend(std::vector<uint8_t> mask)
      : gl_(test::glTestContext()), mask_(std::move(mask)) {}

  std::string description() const override { return gl_.description(); }
  ir::DeviceLimits limits() const override { return gl_.limits(); }
  void setScene(const scene::Scene& scene, const rays::RayScene* rays) override {
    gl_.setScene(scene, rays);
  }
  void setResponseClasses(const physics::ResponseClassTable& classes) override {
    gl_.setResponseClasses(classes);
  }
  void setSurfaces(std::unique_ptr<ir::SurfaceImage> samples,
                   std::unique_ptr<ir::SurfaceImage> centres) override {
    gl_.setSurfaces(std::move(samples), std::move(centres));
  }
  ir::CentreSurfaces prepareSurfaces(const capture::RenderJob& job) override {
    return gl_.prepareSurfaces(job);
  }
  void setSampledPixels(const std::vector<uint8_t>& driverMask) override {
    ASSERT_EQ(driverMask.size(), mask_.size());
    ++maskCalls;
    gl_.setSampledPixels(mask_);
  }
  std::vector<ir::Vpl> generateVpls(const capture::RenderJob& job) override {
    return gl_.generateVpls(job);
  }
  void setVpls(const std::vector<ir::Vpl>& vpls) override { gl_.setVpls(vpls); }
  std::size_t fixedBytes() const override { return gl_.fixedBytes(); }
  std::size_t visibilityBytesPerVpl() const override { return gl_.visibilityBytesPerVpl(); }
  void allocate(std::size_t pixels, std::size_t vpls) override { gl_.allocate(pixels, vpls); }
  void buildVisibility(std::size_t first, std::size_t count) override {
    gl_.buildVisibility(first, count);
  }
  void beginSegment(std::size_t first, std::size_t count) override {
    gl_.beginSegment(first, count);
  }
  void gatherDirect() override { gl_.gatherDirect(); }
  void gatherIndirect(std::size_t first, std::size_t count) override {
    gl_.gatherIndirect(first, count);
  }
  void takeIndirect(float* indirect) override { gl_.takeIndirect(indirect); }
  void readSegment(float* direct, float* indirect, AxisLoss& offAxis) override {
    gl_.readSegment(direct, indirect, offAxis);
  }

  static inline int maskCalls = 0;

 private:
  GlBackend gl_;
  std::vector<uint8_t> mask_;
};

capture::VolumeCollector render(const capture::RenderJob& job,
                                std::unique_ptr<ir::IrBackend> backend) {
  capture::VolumeCollector volume(job.camera().width, job.camera().height, job.settings.time,
                                  capture::kChannels);
  ir::IrRenderer(std::move(backend)).render(job, volume);
  return volume;
}

capture::VolumeCollector renderGl(const capture::RenderJob& job) {
  return render(job, std::make_unique<GlBackend>(test::glTestContext()));
}

// `job` with adaptive samples and `mask` for the driver's edge pixels.
capture::VolumeCollector renderMasked(capture::RenderJob job, const std::vector<uint8_t>& mask) {
  job.settings.adaptive_pixel_samples = true;
  const int callsBefore = HandMaskedBackend::maskCalls;
  capture::VolumeCollector volume = render(job, std::make_unique<HandMaskedBackend>(mask));
  EXPECT_EQ(HandMaskedBackend::maskCalls, callsBefore + 1);
  return volume;
}

struct CornellBox {
  scene::Scene scene = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
  capture::RenderJob job(capture::Visibility visibility, int32_t samples) const {
    capture::RenderJob j = test::cornellBoxJob(scene, 16, 200, 0.01);
    j.settings.shadow_map_resolution = 256;
    j.settings.indirect.rsm_resolution = 8;
    j.settings.indirect.ism_resolution = 32;
    j.settings.indirect.points_per_vpl = 300;
    j.settings.indirect.visibility = visibility;
    j.settings.pixel_samples = samples;
    return j;
  }
};

// A hand mask that crosses the box's edges and flat walls alike: blocks of
// 3 x 2 pixels, alternately sampled and not.
std::vector<uint8_t> blockMask(int32_t width, int32_t height) {
  std::vector<uint8_t> mask(static_cast<std::size_t>(width) * height);
  for (int32_t y = 0; y < height; ++y) {
    for (int32_t x = 0; x < width; ++x) mask[y * width + x] = (x / 3 + y / 2) % 2;
  }
  return mask;
}

bool samePixel(const TransientVolume& a, const TransientVolume& b, int32_t x, int32_t y) {
  for (int32_t t = 0; t < a.bins(); ++t) {
    for (int32_t c = 0; c < a.channels(); ++c) {
      const std::size_t i = a.index(y, x, t, c);
      if (a.data()[i] != b.data()[i]) return false;
    }
  }
  return true;
}

// Each pixel of `adaptive` against the same pixel of `one` (mask 0) or
// `many` (mask 1), exactly. The references must differ in pixels of both
// kinds, or the comparison could not tell them apart.
void expectPixelsFromTheirReference(const char* part, const TransientVolume& adaptive,
                                    const TransientVolume& one, const TransientVolume& many,
                                    const std::vector<uint8_t>& mask) {
  SCOPED_TRACE(part);
  int wrong = 0, telling[2] = {0, 0};
  for (int32_t y = 0; y < adaptive.height(); ++y) {
    for (int32_t x = 0; x < adaptive.width(); ++x) {
      const bool sampled = mask[y * adaptive.width() + x] != 0;
      if (!samePixel(one, many, x, y)) ++telling[sampled];
      if (!samePixel(adaptive, sampled ? many : one, x, y)) {
        if (++wrong <= 5) ADD_FAILURE() << "pixel (" << x << ", " << y << "), mask " << sampled;
      }
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(telling[0], 10) << "masked-out pixels where 1 and N x N samples differ";
  EXPECT_GT(telling[1], 10) << "masked-in pixels where 1 and N x N samples differ";
}

struct Variant {
  capture::Visibility visibility;
  int32_t samples;
  bool footprint;
  capture::MaterialModel materials;
  const char* name;
};

TEST(AdaptiveSamplesGLTest, EachPixelIsOneSampleOrNxNAsItsMaskSays) {
  const CornellBox box;
  const Variant variants[] = {
      {capture::Visibility::Ism, 3, true, capture::MaterialModel::Lambertian, "ism, 3 x 3"},
      {capture::Visibility::Exact, 2, true, capture::MaterialModel::Lambertian, "exact, 2 x 2"},
      {capture::Visibility::Ism, 2, true, capture::MaterialModel::Gltf, "ism, 2 x 2, gltf"},
      {capture::Visibility::Ism, 2, false, capture::MaterialModel::Lambertian,
       "ism, 2 x 2, point pixels"},
  };
  for (const Variant& v : variants) {
    SCOPED_TRACE(v.name);
    capture::RenderJob job = box.job(v.visibility, v.samples);
    job.settings.pixel_footprint = v.footprint;
    job.settings.materials = v.materials;
    const std::vector<uint8_t> mask = blockMask(job.camera().width, job.camera().height);
    const capture::VolumeCollector adaptive = renderMasked(job, mask);
    const capture::VolumeCollector many = renderGl(job);
    job.settings.pixel_samples = 1;
    const capture::VolumeCollector one = renderGl(job);
    expectPixelsFromTheirReference("direct", adaptive.direct, one.direct, many.direct, mask);
    expectPixelsFromTheirReference("indirect", adaptive.indirect, one.indirect, many.indirect,
                                   mask);
  }
}

// The driver's own mask (ir::sampledPixels of the centre G-buffer the backend
// returns): the box's silhouettes and creases take N x N samples, its walls
// one, and each pixel is that of its reference render.
TEST(AdaptiveSamplesGLTest, TheDriversEdgePixelsTakeNxNSamples) {
  const CornellBox box;
  capture::RenderJob job = box.job(capture::Visibility::Ism, 2);
  GlBackend backend(test::glTestContext());
  const test::BackendScene prepared(backend, *job.scene);
  const rays::RayScene rays(*job.scene, 0);
  const std::vector<uint8_t> mask = ir::adaptiveSampledPixels(backend.prepareSurfaces(job), job, rays);
  const auto sampled = static_cast<std::size_t>(std::count(mask.begin(), mask.end(), 1));
  EXPECT_GT(sampled, mask.size() / 10);
  EXPECT_LT(sampled, mask.size() * 3 / 4);  // 16 x 16: edges are most of the box
  job.settings.adaptive_pixel_samples = true;
  capture::VolumeCollector adaptive(job.camera().width, job.camera().height, job.settings.time,
                                    capture::kChannels);
  const capture::RenderResult result =
      ir::IrRenderer(std::make_unique<GlBackend>(test::glTestContext())).render(job, adaptive);
  EXPECT_EQ(result.sampledPixels, sampled);
  job.settings.adaptive_pixel_samples = false;
  const capture::VolumeCollector many = renderGl(job);
  job.settings.pixel_samples = 1;
  const capture::VolumeCollector one = renderGl(job);
  expectPixelsFromTheirReference("direct", adaptive.direct, one.direct, many.direct, mask);
  expectPixelsFromTheirReference("indirect", adaptive.indirect, one.indirect, many.indirect, mask);
}

TEST(AdaptiveSamplesGLTest, AnAllOnesMaskGivesTheBytesOfNxNSamples) {
  const CornellBox box;
  for (capture::Visibility visibility : {capture::Visibility::Ism, capture::Visibility::Exact}) {
    SCOPED_TRACE(visibility == capture::Visibility::Ism ? "ism" : "exact");
    const capture::RenderJob job = box.job(visibility, 2);
    const std::vector<uint8_t> ones(
        static_cast<std::size_t>(job.camera().width) * job.camera().height, 1);
    const capture::VolumeCollector adaptive = renderMasked(job, ones);
    const capture::VolumeCollector many = renderGl(job);
    ASSERT_EQ(adaptive.direct.size(), many.direct.size());
    ASSERT_EQ(adaptive.indirect.size(), many.indirect.size());
    const std::size_t bytes = many.direct.size() * sizeof(float);
    EXPECT_EQ(std::memcmp(adaptive.direct.data(), many.direct.data(), bytes), 0);
    EXPECT_EQ(std::memcmp(adaptive.indirect.data(), many.indirect.data(), bytes), 0);
  }
}

// render.indirect.merge_pixel_samples is gathered by the CPU backend only:
// the GL backend refuses it (the config refuses `backend: gl` with it).
TEST(AdaptiveSamplesGLTest, MergedPixelSamplesAreRefused) {
  const CornellBox box;
  capture::RenderJob job = box.job(capture::Visibility::Ism, 2);
  job.settings.indirect.merge_pixel_samples = true;
  capture::VolumeCollector out(job.camera().width, job.camera().height, job.settings.time,
                               capture::kChannels);
  ir::IrRenderer renderer(std::make_unique<GlBackend>(test::glTestContext()));
  EXPECT_THROW(renderer.render(job, out), InputError);
}

}  // namespace
}  // namespace tofsim::render
