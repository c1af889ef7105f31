// The GL backend's pixel models through the IR driver: render.pixel_footprint
// false keeps point sampling (a head-on plane's pixel holds all its light in
// the one bin of its centre's path), and with footprints and 2 x 2 sub-pixel
// samples the bytes still do not depend on the memory budget (the gather adds
// in VPL-then-sample order, whatever the dispatch and batch split).
// tests/cpu/CpuMatchesGlGLTest.cpp compares these volumes with the CPU's.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "support/GlTestContext.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/render/GlBackend.h"

namespace tofsim::render {
namespace {

using namespace capture;

VolumeCollector renderOnGl(const RenderJob& job, RenderResult* result = nullptr) {
  VolumeCollector out(job.camera().width, job.camera().height, job.settings.time, kChannels);
  ir::IrRenderer renderer(std::make_unique<GlBackend>(test::glTestContext()));
  const RenderResult r = renderer.render(job, out);
  if (result != nullptr) *result = r;
  return out;
}

TEST(PixelModelGLTest, PointPixelsPutAHeadOnPlanesLightInTheBinOfTheCentre) {
  test::PlaneJob s;
  s.job.camera().look_at_world = {0.0f, 0.0f, 0.0f};  // head-on, 1.5 m above z = 0
  s.job.settings.pixel_footprint = false;
  s.job.settings.indirect.enabled = false;
  const VolumeCollector out = renderOnGl(s.job);
  const TimeAxis& axis = s.job.settings.time;
  const double start_m = axis.start_m(), width_m = axis.bin_width_m();
  int checked = 0;
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      // The centre ray meets the plane at t = 1.5 / -d.z; light at the camera.
      const glm::dvec3 d(s.job.camera().pixelDirection(x, y));
      const double bins = (2.0 * 1.5 / -d.z - start_m) / width_m;
      int lit = 0, at = -1;
      for (int t = 0; t < axis.bins; ++t) {
        if (out.direct.at(y, x, t, 0) != 0.0f) ++lit, at = t;
      }
      ASSERT_EQ(lit, 1) << "pixel " << x << ", " << y;
      if (std::abs(bins - std::round(bins)) < 1e-3) continue;  // float may round either way
      EXPECT_EQ(at, static_cast<int>(std::floor(bins))) << "pixel " << x << ", " << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, s.job.camera().width * s.job.camera().height * 9 / 10);
}

TEST(PixelModelGLTest, FootprintsWithSubPixelSamplesGiveTheSameBytesWhateverTheBudget) {
  test::CornerJob s(16);
  s.job.settings.pixel_footprint = true;
  s.job.settings.pixel_samples = 2;
  s.job.settings.indirect.visibility = Visibility::Ism;
  s.job.settings.indirect.rsm_resolution = 16;
  s.job.settings.indirect.points_per_vpl = 300;
  s.job.settings.shadow_map_resolution = 128;
  RenderResult unlimited, small;
  s.job.settings.memory_budget_bytes = std::size_t{1} << 30;
  const VolumeCollector a = renderOnGl(s.job, &unlimited);
  s.job.settings.memory_budget_bytes = std::size_t{3} << 20;
  const VolumeCollector b = renderOnGl(s.job, &small);
  EXPECT_EQ(unlimited.segments, 1u);
  EXPECT_EQ(unlimited.vplBatches, 1u);
  EXPECT_GT(small.segments, 1u);
  EXPECT_GT(small.vplBatches, 1u);
  ASSERT_EQ(a.indirect.size(), b.indirect.size());
  EXPECT_EQ(0, std::memcmp(a.direct.data(), b.direct.data(), a.direct.size() * sizeof(float)));
  EXPECT_EQ(0,
            std::memcmp(a.indirect.data(), b.indirect.data(), a.indirect.size() * sizeof(float)));
  double indirect = 0.0;
  for (float v : a.indirect.values()) indirect += v;
  EXPECT_GT(indirect, 0.0);
}

}  // namespace
}  // namespace tofsim::render
