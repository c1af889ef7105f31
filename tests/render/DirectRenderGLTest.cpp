// Closed-form checks of the direct transient render on llvmpipe: a diffuse
// plane under a point light, arrival bins, cos/r^2 falloff, unwarping,
// causality and shadows.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <optional>

#include "support/ClosedForm.h"
#include "support/GlTestContext.h"
#include "support/TestBackends.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::render {
namespace {

using namespace capture;
using test::hitOnPlane;
using test::peakBin;
using test::unambiguousBin;

constexpr double kPi = 3.14159265358979323846;

using PlaneSetup = test::PlaneJob;

// Every test runs on the GL and on the CPU backend.
class DirectRenderGLTest : public test::BackendTest {
 protected:
  VolumeCollector renderJob(const RenderJob& job) const {
    VolumeCollector collector(job.camera().width, job.camera().height, job.settings.time, 3);
    renderer()->render(job, collector);
    return collector;
  }
};

TEST_P(DirectRenderGLTest, PeakLandsInTheBinOfTheRoundTripPath) {
  PlaneSetup s;
  s.job.settings.pixel_footprint = false;  // compares pixel centres' paths (point pixels)
  const VolumeCollector out = renderJob(s.job);
  int checked = 0;
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      const glm::dvec3 p = hitOnPlane(s.job.camera(), x, y);
      const double r = glm::length(p - glm::dvec3(s.job.camera().position_world));
      const auto expected = unambiguousBin(s.job.settings.time, 2.0 * r);
      if (!expected) continue;
      EXPECT_EQ(peakBin(out.direct, y, x), *expected) << "pixel " << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST_P(DirectRenderGLTest, SteadyRadianceFollowsCosineOverDistanceSquared) {
  PlaneSetup s;
  const VolumeCollector out = renderJob(s.job);
  const Image steady = steadyImage(out.direct);
  const glm::dvec3 l(s.job.light.position_world);
  const glm::dvec3 albedo(0.5, 0.4, 0.3);
  const glm::dvec3 intensity(s.job.light.intensity_W_per_sr);
  const auto expectedRadiance = [&](int x, int y, int c) {
    const glm::dvec3 p = hitOnPlane(s.job.camera(), x, y);
    const glm::dvec3 toLight = l - p;
    const double r = glm::length(toLight);
    const double cosTheta = toLight.z / r;
    return albedo[c] / kPi * intensity[c] * cosTheta / (r * r);
  };
  const int cx = s.job.camera().width / 2, cy = s.job.camera().height / 2;
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      for (int c = 0; c < 3; ++c) {
        // Absolute value and ratio to the centre pixel, both within 1%.
        EXPECT_NEAR(steady.at(y, x, c), expectedRadiance(x, y, c),
                    0.01 * expectedRadiance(x, y, c));
        const double ratio = steady.at(y, x, c) / steady.at(cy, cx, c);
        const double expectedRatio = expectedRadiance(x, y, c) / expectedRadiance(cx, cy, c);
        EXPECT_NEAR(ratio, expectedRatio, 0.01 * expectedRatio);
      }
    }
  }
}

TEST_P(DirectRenderGLTest, CameraUnwarpShiftsPeaksByTheCameraDelay) {
  PlaneSetup s;
  s.job.settings.pixel_footprint = false;  // compares pixel centres' paths (point pixels)
  s.job.settings.time = TimeAxis{1.0 / kSpeedOfLight_m_per_s, 0.002 / kSpeedOfLight_m_per_s, 1200};
  s.job.settings.time.camera_unwarp = true;
  const VolumeCollector out = renderJob(s.job);
  int checked = 0;
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      const glm::dvec3 p = hitOnPlane(s.job.camera(), x, y);
      const double r = glm::length(p - glm::dvec3(s.job.camera().position_world));
      // Round trip 2r minus the camera leg r: only the light -> surface path.
      const auto expected = unambiguousBin(s.job.settings.time, 2.0 * r - r);
      if (!expected) continue;
      EXPECT_EQ(peakBin(out.direct, y, x), *expected);
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST_P(DirectRenderGLTest, NoEnergyBeforeTheDirectPath) {
  PlaneSetup s;
  s.job.settings.pixel_footprint = false;  // compares pixel centres' paths (point pixels)
  const VolumeCollector out = renderJob(s.job);
  const TransientVolume total = out.total();
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      const glm::dvec3 p = hitOnPlane(s.job.camera(), x, y);
      const double r = glm::length(p - glm::dvec3(s.job.camera().position_world));
      const int firstAllowed = s.job.settings.time.binOf((2.0 * r - 1e-6) / kSpeedOfLight_m_per_s);
      for (int t = 0; t < firstAllowed; ++t) {
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(total.at(y, x, t, c), 0.0f) << x << "," << y << " t=" << t;
      }
    }
  }
}

TEST_P(DirectRenderGLTest, OccluderRemovesDirectLightBehindIt) {
  PlaneSetup s;
  const float occluderZ = 0.75f, occluderSize = 0.6f;
  test::addQuad(s.scene, glm::vec3(0.0f, 0.0f, occluderZ), glm::vec3(0, 0, 1), occluderSize,
                glm::vec3(0.5f));
  s.job.light.position_world = {0.0f, 0.0f, 1.5f};
  s.job.camera().position_world = {1.2f, 0.3f, 1.6f};
  s.job.camera().look_at_world = {0.0f, 0.0f, 0.0f};
  s.job.settings.shadow_map_resolution = 512;
  s.job.settings.time = TimeAxis{0.0, 0.01 / kSpeedOfLight_m_per_s, 1000};
  const VolumeCollector out = renderJob(s.job);
  const Image steady = steadyImage(out.direct);
  int shadowed = 0, lit = 0;
  const glm::dvec3 l(s.job.light.position_world);
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      const glm::dvec3 onOccluder = hitOnPlane(s.job.camera(), x, y, occluderZ);
      const double half = occluderSize / 2.0;
      if (std::abs(onOccluder.x) < half + 0.05 && std::abs(onOccluder.y) < half + 0.05) continue;
      const glm::dvec3 p = hitOnPlane(s.job.camera(), x, y);
      if (std::max(std::abs(p.x), std::abs(p.y)) > 2.9) continue;  // beyond the plane's edge
      // Where the segment light -> p crosses the occluder's plane.
      const glm::dvec3 q = l + (p - l) * ((occluderZ - l.z) / (p.z - l.z));
      const double m = std::max(std::abs(q.x), std::abs(q.y));
      if (m < half - 0.03) {
        EXPECT_EQ(steady.at(y, x, 0), 0.0f) << "shadowed pixel " << x << "," << y;
        ++shadowed;
      } else if (m > half + 0.03) {
        EXPECT_GT(steady.at(y, x, 0), 0.0f) << "lit pixel " << x << "," << y;
        ++lit;
      }
    }
  }
  EXPECT_GT(shadowed, 20);
  EXPECT_GT(lit, 200);
}

TEST_P(DirectRenderGLTest, SameJobGivesIdenticalBytesWhateverTheMemoryBudget) {
  PlaneSetup s;
  s.job.settings.shadow_map_resolution = 256;
  const auto render = [&](VolumeCollector& out) { return renderer()->render(s.job, out); };
  VolumeCollector a(s.job.camera().width, s.job.camera().height, s.job.settings.time, 3);
  EXPECT_EQ(render(a).segments, 1u);
  s.job.settings.memory_budget_bytes = 8 << 20;  // forces many segments
  VolumeCollector b(s.job.camera().width, s.job.camera().height, s.job.settings.time, 3);
  EXPECT_GT(render(b).segments, 4u);
  ASSERT_EQ(a.direct.size(), b.direct.size());
  EXPECT_EQ(0, std::memcmp(a.direct.data(), b.direct.data(), a.direct.size() * sizeof(float)));
}

TOFSIM_ON_BOTH_BACKENDS(DirectRenderGLTest);

}  // namespace
}  // namespace tofsim::render
