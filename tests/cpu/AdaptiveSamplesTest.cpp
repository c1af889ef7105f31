// render.adaptive_pixel_samples on the CPU backend, through the IR driver:
// on the Cornell box every pixel of the adaptive render has exactly the bytes
// of that pixel in the pixel_samples: 1 render (pixels off every edge) or in
// the pixel_samples: N render (edge pixels), direct and indirect, with the
// footprint and with point pixels; the driver counts the sampled pixels.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>

#include "support/BackendScene.h"
#include "support/CpuRender.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/ir/SampledPixels.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::cpu {
namespace {

using namespace capture;

using test::CpuRender;
using test::renderOnCpu;

bool samePixel(const TransientVolume& a, const TransientVolume& b, int32_t y, int32_t x) {
  const std::size_t floats = static_cast<std::size_t>(a.bins()) * a.channels();
  const std::size_t first = (static_cast<std::size_t>(y) * a.width() + x) * floats;
  return std::memcmp(a.data() + first, b.data() + first, floats * sizeof(float)) == 0;
}

// The mask the driver computes, from the backend's own centre G-buffer.
std::vector<uint8_t> sampledMask(const RenderJob& job) {
  CpuBackend backend(CpuBackendOptions{2, true});
  const test::BackendScene prepared(backend, *job.scene);
  return ir::sampledPixels(backend.prepareSurfaces(job), job.camera().width, job.camera().height);
}

void expectComposition(RenderJob job, int32_t n) {
  job.settings.pixel_samples = n;
  job.settings.adaptive_pixel_samples = true;
  const CpuRender adaptive = renderOnCpu(job);
  const std::vector<uint8_t> sampled = sampledMask(job);
  job.settings.adaptive_pixel_samples = false;
  const CpuRender all = renderOnCpu(job);
  job.settings.pixel_samples = 1;
  const CpuRender one = renderOnCpu(job);

  const auto count = static_cast<std::size_t>(std::count(sampled.begin(), sampled.end(), 1));
  EXPECT_EQ(adaptive.result.sampledPixels, count);
  // The box's silhouettes, the walls' creases, the ceiling light's rim: some
  // pixels, far from all (measured at 24 x 24: about a third).
  EXPECT_GT(count, sampled.size() / 10);
  EXPECT_LT(count, sampled.size() / 2);
  int mismatches = 0;
  for (int32_t y = 0; y < job.camera().height; ++y) {
    for (int32_t x = 0; x < job.camera().width; ++x) {
      const CpuRender& expected =
          sampled[static_cast<std::size_t>(y) * job.camera().width + x] ? all : one;
      const bool same = samePixel(adaptive.volume.direct, expected.volume.direct, y, x) &&
                        samePixel(adaptive.volume.indirect, expected.volume.indirect, y, x);
      if (!same && ++mismatches <= 5) ADD_FAILURE() << "pixel " << x << "," << y;
    }
  }
  EXPECT_EQ(mismatches, 0);
}

class AdaptiveSamplesTest : public ::testing::Test {
 protected:
  scene::Scene scene_ = scene::loadGltf(TOFSIM_SOURCE_DIR "/configs/scenes/cornell_box.gltf");
};

TEST_F(AdaptiveSamplesTest, EachPixelIsTheOneSampleOrTheSubSampledRendersWithTheFootprint) {
  RenderJob job = test::cornellBoxJob(scene_, 24, 120, 0.02);
  job.settings.indirect.rsm_resolution = 16;
  job.settings.indirect.visibility = Visibility::Ism;
  expectComposition(job, 3);
}

TEST_F(AdaptiveSamplesTest, EachPixelIsTheOneSampleOrTheSubSampledRendersWithPointPixels) {
  RenderJob job = test::cornellBoxJob(scene_, 24, 120, 0.02);
  job.settings.pixel_footprint = false;
  job.settings.indirect.rsm_resolution = 16;
  job.settings.indirect.visibility = Visibility::Exact;
  expectComposition(job, 2);
}

TEST_F(AdaptiveSamplesTest, OffOrWithOneSampleNothingChanges) {
  RenderJob job = test::cornellBoxJob(scene_, 16, 80, 0.02);
  job.settings.indirect.rsm_resolution = 16;
  const CpuRender plain = renderOnCpu(job);
  job.settings.adaptive_pixel_samples = true;  // pixel_samples 1: nothing to adapt
  const CpuRender adaptiveOne = renderOnCpu(job);
  EXPECT_EQ(adaptiveOne.result.sampledPixels, 0u);
  for (int32_t y = 0; y < job.camera().height; ++y) {
    for (int32_t x = 0; x < job.camera().width; ++x) {
      ASSERT_TRUE(samePixel(plain.volume.direct, adaptiveOne.volume.direct, y, x));
      ASSERT_TRUE(samePixel(plain.volume.indirect, adaptiveOne.volume.indirect, y, x));
    }
  }
}

}  // namespace
}  // namespace tofsim::cpu
