// The memory plan counts the delayed response classes' regions of GL's
// footprint buffer (issue 41, core/physics/temporal_response.md): with the
// wall delayed the plan makes smaller segments at the same
// render.memory_budget, stays within it, and the bytes do not depend on the
// segments, with and without the pixel footprint (the classes' regions then
// follow a region 0 of their own).

#include <gtest/gtest.h>

#include <cstring>

#include "support/GlTestContext.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/render/GlBackend.h"

namespace tofsim::render {
namespace {

using namespace capture;

VolumeCollector renderOnGl(const RenderJob& job, RenderResult& result) {
  VolumeCollector out(job.camera().width, job.camera().height, job.settings.time, kChannels);
  ir::IrRenderer renderer(std::make_unique<GlBackend>(test::glTestContext()));
  result = renderer.render(job, out);
  return out;
}

bool sameBytes(const TransientVolume& a, const TransientVolume& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(ResponseMemoryGLTest, DelayedClassesShrinkTheSegmentsAndKeepTheBytes) {
  for (const bool footprint : {true, false}) {
    SCOPED_TRACE(footprint ? "pixel footprint" : "point pixels");
    test::CornerJob s(12);
    s.job.settings.pixel_footprint = footprint;
    s.job.settings.indirect.rsm_resolution = 8;
    s.job.settings.indirect.points_per_vpl = 100;
    s.job.settings.shadow_map_resolution = 128;
    s.job.settings.memory_budget_bytes = std::size_t{3} << 20;
    RenderResult instant, delayed, whole;
    renderOnGl(s.job, instant);
    physics::ResponseKernel wall;
    wall.lifetime_s = 0.5e-9;
    wall.fraction = 0.6;
    s.scene.materials[1].scatteringDelay = wall;
    const VolumeCollector split = renderOnGl(s.job, delayed);
    s.job.settings.memory_budget_bytes = std::size_t{1} << 30;
    const VolumeCollector one = renderOnGl(s.job, whole);
    EXPECT_GT(delayed.segments, instant.segments);
    EXPECT_LE(delayed.peakGpuBytes, std::size_t{3} << 20);
    EXPECT_EQ(whole.segments, 1u);
    EXPECT_TRUE(sameBytes(one.direct, split.direct));
    EXPECT_TRUE(sameBytes(one.indirect, split.indirect));
    EXPECT_EQ(whole.offAxis.after, delayed.offAxis.after);
  }
}

}  // namespace
}  // namespace tofsim::render
