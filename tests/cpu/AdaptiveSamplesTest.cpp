// render.adaptive_pixel_samples on the CPU backend, through the IR driver:
// on the Cornell box every pixel of the adaptive render has exactly the bytes
// of that pixel in the pixel_samples: 1 render (pixels off every edge) or in
// the pixel_samples: N render (edge pixels), direct and indirect, with the
// footprint and with point pixels; the driver counts the sampled pixels.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "support/BackendScene.h"
#include "support/CpuRender.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/ir/LitPixels.h"
#include "tofsim/rays/RayScene.h"
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
  const rays::RayScene rays(*job.scene, 0);
  return ir::adaptiveSampledPixels(backend.prepareSurfaces(job), job, rays);
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

// A shadow on a flat floor: its edge crosses pixels the G-buffer sees as one
// plane. The driver's light rays (ir::litPixels) give them their N x N
// samples, so the adaptive render's direct light there is the full N x N
// render's, where one sample at the centre gives a pixel all of its light or
// none.
TEST(AdaptiveShadowEdgeTest, AShadowEdgeInsideFlatPixelsTakesTheSubSamples) {
  scene::Scene scene = test::makePlane(3.0f, glm::vec3(0.6f));
  test::addQuad(scene, glm::vec3(0.0f, 0.0f, 0.4f), glm::vec3(0.0f, 0.0f, 1.0f), 0.2f,
                glm::vec3(0.5f));  // the occluder, 0.4 m above the floor
  RenderJob job;
  job.scene = &scene;
  job.camera().position_world = {0.0f, 0.0f, 1.5f};
  job.camera().look_at_world = {0.0f, 0.01f, 0.0f};
  job.camera().fov_y_deg = 60.0f;
  job.camera().width = 32;
  job.camera().height = 32;
  job.light.position_world = {0.5f, 0.0f, 1.2f};  // the shadow lands beside the occluder's image
  job.light.intensity_W_per_sr = glm::vec3(1.0f);
  job.settings.time = TimeAxis{1.5 / kSpeedOfLight_m_per_s, 0.01 / kSpeedOfLight_m_per_s, 400};
  job.settings.indirect.enabled = false;
  job.settings.pixel_samples = 4;
  const auto steady = [](const CpuRender& r) {
    const TransientVolume& v = r.volume.direct;
    std::vector<double> light(static_cast<std::size_t>(v.width()) * v.height(), 0.0);
    const std::size_t perPixel = static_cast<std::size_t>(v.bins()) * v.channels();
    for (std::size_t i = 0; i < v.size(); ++i) light[i / perPixel] += v.data()[i];
    return light;
  };
  const std::vector<double> all = steady(renderOnCpu(job));
  job.settings.adaptive_pixel_samples = true;
  const CpuRender adaptiveRender = renderOnCpu(job);
  const std::vector<double> adaptive = steady(adaptiveRender);
  job.settings.pixel_samples = 1;
  const std::vector<double> one = steady(renderOnCpu(job));
  const auto l1 = [&](const std::vector<double>& a) {
    double diff = 0.0, sum = 0.0;
    for (std::size_t p = 0; p < all.size(); ++p) diff += std::abs(a[p] - all[p]), sum += all[p];
    return diff / sum;
  };
  // The occluder's silhouette and the shadow's edges: some pixels, not most.
  EXPECT_GT(adaptiveRender.result.sampledPixels, 32u * 2);
  EXPECT_LT(adaptiveRender.result.sampledPixels, 32u * 32 / 3);
  // Off the edges one sample with the footprint differs from 4 x 4 only by
  // the light's curvature across a pixel; at a shadow's edge by up to all of it.
  EXPECT_GT(l1(one), 0.01) << "the shadow's edges must matter here";
  std::printf("direct light, relative L1 to 4 x 4 everywhere: one sample %.4f, adaptive %.5f\n", l1(one), l1(adaptive));
  EXPECT_LT(l1(adaptive), 0.05 * l1(one));
}

}  // namespace
}  // namespace tofsim::cpu
