// The reference renderer's direct term against the GL renderer's direct
// gather on the same jobs: both evaluate the same formula at the same pixel
// centres, so they agree to rounding, not just statistically. Shadow maps are
// not involved: in these scenes nothing stands between light and surface.
// Measured: up to 0.45% apart in two pixels of the spot's falloff near its
// outer edge, under 1e-4 elsewhere. Most likely the rasterizer's sub-pixel
// vertex snapping (llvmpipe: 1/256 pixel) moving the G-buffer point, which
// matters only where radiance changes steeply; not investigated further.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>

#include "../support/GlTestContext.h"
#include "RenderReference.h"
#include "support/ClosedForm.h"
#include "tofsim/compare/VolumeComparison.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/render/GlBackend.h"

namespace tofsim::reference {
namespace {

using namespace capture;

// Index of the only non-zero bin of a pixel's red channel, -1 when dark.
int litBin(const TransientVolume& v, int y, int x) {
  int found = -1;
  for (int t = 0; t < v.bins(); ++t) {
    if (v.at(y, x, t, 0) != 0.0f) {
      EXPECT_EQ(found, -1) << "more than one direct bin at " << x << "," << y;
      found = t;
    }
  }
  return found;
}

void expectSameDirectLight(RenderJob job) {
  job.settings.indirect.enabled = false;
  job.settings.pixel_footprint = false;  // compares pixel centres (point pixels)
  VolumeCollector gl(job.camera().width, job.camera().height, job.settings.time, 3);
  ir::IrRenderer(std::make_unique<render::GlBackend>(test::glTestContext())).render(job, gl);
  ReferenceSettings settings;
  settings.pixel_filter = PixelFilter::Point;  // compares pixel centres
  settings.bounces = 1;
  settings.threads = 2;
  const VolumeCollector ref = test::renderReference(job, settings);

  const compare::VolumeComparison metrics = compare::compareVolumes(gl.direct, ref.direct);
  EXPECT_LT(metrics.steadyRelativeL1, 1e-4);
  const Image steadyGl = steadyImage(gl.direct), steadyRef = steadyImage(ref.direct);
  int lit = 0, binFlips = 0, close = 0;
  for (int y = 0; y < job.camera().height; ++y) {
    for (int x = 0; x < job.camera().width; ++x) {
      bool pixelClose = true;
      for (int c = 0; c < 3; ++c) {
        const float r = steadyRef.at(y, x, c), g = steadyGl.at(y, x, c);
        EXPECT_NEAR(g, r, 1e-2f * r + 1e-12f) << x << "," << y << " c" << c;
        pixelClose = pixelClose && std::abs(g - r) <= 1e-4f * r + 1e-12f;
      }
      if (pixelClose) ++close;
      const int bGl = litBin(gl.direct, y, x), bRef = litBin(ref.direct, y, x);
      if (bRef < 0) continue;
      ++lit;
      // Float rounding of the path in the shader may cross a bin edge.
      EXPECT_LE(std::abs(bGl - bRef), 1) << x << "," << y;
      if (bGl != bRef) ++binFlips;
    }
  }
  EXPECT_GT(lit, job.camera().width * job.camera().height / 2);
  EXPECT_GE(close, job.camera().width * job.camera().height * 98 / 100) << "pixels within 1e-4";
  EXPECT_LE(binFlips, lit / 50) << "more than 2% of pixels in a neighbouring bin";
}

TEST(ReferenceMatchesGlDirectGLTest, PlaneUnderAPointLight) {
  test::PlaneJob s;
  expectSameDirectLight(s.job);
}

TEST(ReferenceMatchesGlDirectGLTest, CornerUnderASpotLightWithUnwarping) {
  test::CornerJob s(32);
  s.job.light.type = Light::Type::Spot;
  s.job.light.direction_world = glm::normalize(glm::vec3(-0.5f, -1.2f, -1.0f));
  s.job.light.cone_half_angle_deg = 50.0f;
  s.job.light.cone_falloff_deg = 10.0f;
  s.job.settings.time.camera_unwarp = true;
  s.job.settings.time.index_of_refraction = 1.2;
  expectSameDirectLight(s.job);
}

}  // namespace
}  // namespace tofsim::reference
