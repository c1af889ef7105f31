// The memory plan counts the delayed response classes' buffers (issue 41,
// core/physics/temporal_response.md): a scene with delayed materials plans
// smaller segments than the same scene without at the same
// render.memory_budget, never more than the budget, and renders the same
// bytes whatever segments the budget makes.

#include <gtest/gtest.h>

#include <cstring>

#include "support/CpuRender.h"
#include "support/TestJobs.h"
#include "tofsim/physics/TemporalResponse.h"

namespace tofsim::cpu {
namespace {

bool sameBytes(const TransientVolume& a, const TransientVolume& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(ResponseMemoryTest, DelayedClassesShrinkTheSegmentsAndKeepTheBytes) {
  test::CornerJob s(12);
  s.job.settings.indirect.rsm_resolution = 8;
  s.job.settings.indirect.points_per_vpl = 100;
  s.job.settings.memory_budget_bytes = std::size_t{3} << 20;
  const test::CpuRender instant = test::renderOnCpu(s.job);
  // The wall delays 60 % of its light by a 0.5 ns lifetime: classes {wall},
  // {wall, wall} (its light on the floor and back), and a cascade's scratch.
  physics::ResponseKernel wall;
  wall.lifetime_s = 0.5e-9;
  wall.fraction = 0.6;
  s.scene.materials[1].scatteringDelay = wall;
  const test::CpuRender delayed = test::renderOnCpu(s.job);
  // 1000 bins: 24 kB a histogram, twice; the footprint buffer's 48 kB, and
  // 3 more such regions with the classes.
  EXPECT_GT(delayed.result.segments, instant.result.segments);
  EXPECT_LE(delayed.result.peakGpuBytes, s.job.settings.memory_budget_bytes);
  EXPECT_GT(delayed.result.peakGpuBytes, s.job.settings.memory_budget_bytes / 2);
  s.job.settings.memory_budget_bytes = std::size_t{1} << 30;
  const test::CpuRender whole = test::renderOnCpu(s.job);
  EXPECT_EQ(whole.result.segments, 1u);
  EXPECT_GT(delayed.result.segments, 2u);
  EXPECT_TRUE(sameBytes(whole.volume.direct, delayed.volume.direct));
  EXPECT_TRUE(sameBytes(whole.volume.indirect, delayed.volume.indirect));
  EXPECT_EQ(whole.result.offAxis.after, delayed.result.offAxis.after);
  double sum = 0.0;
  for (float v : whole.volume.indirect.values()) sum += v;
  EXPECT_GT(sum, 0.0);
}

}  // namespace
}  // namespace tofsim::cpu
