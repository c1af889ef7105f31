// The CPU IR backend without GL: closed-form direct light on the plane,
// bytes independent of the thread count and of the segment / batch plan.
// This program links no GL or EGL library at all.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "support/ClosedForm.h"
#include "support/CpuRender.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"

namespace tofsim::cpu {
namespace {

using test::CpuRender;
using test::renderOnCpu;

bool sameBytes(const TransientVolume& a, const TransientVolume& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(CpuBackendTest, PlaneDirectPeakIsInTheBinOfTheRoundTrip) {
  test::PlaneJob s;
  s.job.settings.pixel_footprint = false;  // compares pixel centres' paths (point pixels)
  s.job.settings.indirect.enabled = false;
  const CpuRender out = renderOnCpu(s.job, {2, true});
  int checked = 0;
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      const glm::dvec3 p = test::hitOnPlane(s.job.camera(), x, y);
      const double r = glm::length(p - glm::dvec3(s.job.camera().position_world));
      const auto expected = test::unambiguousBin(s.job.settings.time, 2.0 * r);
      if (!expected) continue;
      EXPECT_EQ(test::peakBin(out.volume.direct, y, x), *expected) << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(CpuBackendTest, PlaneDirectRadianceIsAlbedoOverPiTimesCosOverR2) {
  test::PlaneJob s;
  s.job.settings.indirect.enabled = false;
  const CpuRender out = renderOnCpu(s.job, {2, true});
  const Image steady = steadyImage(out.volume.direct);
  const glm::dvec3 l(s.job.light.position_world);
  const glm::dvec3 albedo(0.5, 0.4, 0.3);
  const glm::dvec3 intensity(s.job.light.intensity_W_per_sr);
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      const glm::dvec3 p = test::hitOnPlane(s.job.camera(), x, y);
      const double r = glm::length(l - p);
      const double cosTheta = (l - p).z / r;
      for (int c = 0; c < 3; ++c) {
        // Ray hits lie on the plane to float precision: 1e-4 relative.
        const double expected = albedo[c] / M_PI * intensity[c] * cosTheta / (r * r);
        EXPECT_NEAR(steady.at(y, x, c), expected, 1e-4 * expected) << x << "," << y;
      }
    }
  }
  EXPECT_EQ(out.result.offAxis.total(), 0.0);
}

TEST(CpuBackendTest, LightBeforeTheAxisIsCountedBeforeIt) {
  test::PlaneJob s;
  s.job.settings.indirect.enabled = false;
  s.job.settings.time.start_s = 1e-6;  // 300 m: every direct path arrives before
  const CpuRender out = renderOnCpu(s.job, {2, true});
  EXPECT_GT(out.result.offAxis.before, 0.0);
  EXPECT_EQ(out.result.offAxis.after, 0.0);
  // All of it: the radiance the same render puts on its axis.
  test::PlaneJob onAxis;
  onAxis.job.settings.indirect.enabled = false;
  double total = 0.0;
  const CpuRender reference = renderOnCpu(onAxis.job, {2, true});
  for (float v : reference.volume.direct.values()) total += v;
  EXPECT_NEAR(out.result.offAxis.before, total, 1e-5 * total);
}

class CpuDeterminismTest : public ::testing::TestWithParam<capture::Visibility> {};

TEST_P(CpuDeterminismTest, OneTwoAndThreeThreadsGiveTheSameBytes) {
  for (const bool adaptive : {false, true}) {
    SCOPED_TRACE(adaptive ? "2 x 2 samples at edges" : "one sample");
    test::CornerJob s(20);
    s.job.settings.indirect.visibility = GetParam();
    s.job.settings.indirect.rsm_resolution = 12;
    s.job.settings.indirect.points_per_vpl = 300;
    s.job.settings.pixel_samples = adaptive ? 2 : 1;
    s.job.settings.adaptive_pixel_samples = adaptive;
    const CpuRender one = renderOnCpu(s.job, {1, true});
    ASSERT_GT(one.result.vpls, 0u);
    for (int threads : {2, 3}) {
      const CpuRender many = renderOnCpu(s.job, {threads, true});
      EXPECT_TRUE(sameBytes(one.volume.direct, many.volume.direct)) << threads << " threads";
      EXPECT_TRUE(sameBytes(one.volume.indirect, many.volume.indirect)) << threads << " threads";
      EXPECT_EQ(one.result.offAxis.before, many.result.offAxis.before);
      EXPECT_EQ(one.result.offAxis.after, many.result.offAxis.after);
    }
  }
}

TEST_P(CpuDeterminismTest, SegmentsAndBatchesDoNotChangeTheBytes) {
  // With the pixel footprint (the default), with one and with 2 x 2 samples
  // per pixel (whose additions must not depend on where batches start), and
  // 2 x 2 at the edges only (segments then hold different sample counts).
  const struct {
    int samples;
    bool adaptive;
  } models[] = {{1, false}, {2, false}, {2, true}};
  for (const auto [samples, adaptive] : models) {
    SCOPED_TRACE(testing::Message()
                 << samples << " x " << samples << (adaptive ? " at edges" : ""));
    test::CornerJob s(20);
    s.job.settings.indirect.visibility = GetParam();
    s.job.settings.indirect.rsm_resolution = 12;
    s.job.settings.indirect.points_per_vpl = 300;
    s.job.settings.indirect.ism_resolution = 64;  // ~22 kB per VPL: ISMs outgrow the budget below
    s.job.settings.pixel_samples = samples;
    s.job.settings.adaptive_pixel_samples = adaptive;
    const CpuRender whole = renderOnCpu(s.job, {2, true});
    // A budget just above what the render holds for its whole length: many
    // segments, and (with ISMs) many VPL batches.
    s.job.settings.memory_budget_bytes = std::size_t{3} << 20;
    const CpuRender split = renderOnCpu(s.job, {2, true});
    EXPECT_EQ(whole.result.segments, 1u);
    EXPECT_GT(split.result.segments, 2u);
    EXPECT_EQ(whole.result.sampledPixels, split.result.sampledPixels);
    if (adaptive) {
      EXPECT_GT(whole.result.sampledPixels, 0u);
    }
    if (GetParam() == capture::Visibility::Ism) {
      EXPECT_GT(split.result.vplBatches, 1u);
    }
    EXPECT_TRUE(sameBytes(whole.volume.direct, split.volume.direct)) << samples;
    EXPECT_TRUE(sameBytes(whole.volume.indirect, split.volume.indirect)) << samples;
    double sum = 0.0;
    for (float v : whole.volume.indirect.values()) sum += v;
    EXPECT_GT(sum, 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Visibility, CpuDeterminismTest,
                         ::testing::Values(capture::Visibility::Ism, capture::Visibility::Exact),
                         [](const auto& info) {
                           return info.param == capture::Visibility::Ism ? "Ism" : "Exact";
                         });

TEST(CpuBackendTest, NoVisibilityIsAnUpperBoundOfExactVisibility) {
  test::CornerJob s(16);
  s.job.settings.indirect.visibility = capture::Visibility::Exact;
  s.job.settings.indirect.rsm_resolution = 12;
  const CpuRender exact = renderOnCpu(s.job, {2, true});
  const CpuRender none = renderOnCpu(s.job, {2, false});
  for (std::size_t i = 0; i < exact.volume.indirect.size(); ++i) {
    ASSERT_LE(exact.volume.indirect.values()[i], none.volume.indirect.values()[i]) << i;
  }
}

}  // namespace
}  // namespace tofsim::cpu
