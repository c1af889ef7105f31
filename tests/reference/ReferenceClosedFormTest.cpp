// Closed-form checks of the reference renderer's direct term, mirroring
// tests/render/DirectRenderGLTest.cpp: a diffuse plane under a point light,
// arrival bins, cos/r^2 falloff, unwarping, causality, exact shadows, the
// light seen by the camera, and energy off the time axis.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "RenderReference.h"
#include "support/ClosedForm.h"

namespace tofsim::reference {
namespace {

using test::hitOnPlane;
using test::peakBin;
using test::unambiguousBin;

using namespace capture;

constexpr double kPi = 3.14159265358979323846;

ReferenceSettings directOnly() {
  ReferenceSettings s;
  s.pixel_filter = PixelFilter::Point;  // compares pixel centres
  s.bounces = 1;
  s.threads = 2;
  return s;
}

TEST(ReferenceClosedFormTest, PeakLandsInTheBinOfTheRoundTripPath) {
  test::PlaneJob s;
  const VolumeCollector out = test::renderReference(s.job, directOnly());
  int checked = 0;
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      const double r =
          glm::length(hitOnPlane(s.job.camera(), x, y) - glm::dvec3(s.job.camera().position_world));
      const auto expected = unambiguousBin(s.job.settings.time, 2.0 * r);
      if (!expected) continue;
      EXPECT_EQ(peakBin(out.direct, y, x), *expected) << "pixel " << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(ReferenceClosedFormTest, SteadyRadianceFollowsCosineOverDistanceSquared) {
  test::PlaneJob s;
  RenderResult result;
  const VolumeCollector out = test::renderReference(s.job, directOnly(), &result);
  const Image steady = steadyImage(out.direct);
  const glm::dvec3 l(s.job.light.position_world);
  const glm::dvec3 albedo(0.5, 0.4, 0.3);
  const glm::dvec3 intensity(s.job.light.intensity_W_per_sr);
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      const glm::dvec3 p = hitOnPlane(s.job.camera(), x, y);
      const double r = glm::length(l - p);
      const double cosTheta = (l - p).z / r;
      // The depth the renderer reports is the camera-to-surface distance.
      EXPECT_NEAR(result.depth_m.at(y, x, 0),
                  glm::length(p - glm::dvec3(s.job.camera().position_world)), 1e-5);
      for (int c = 0; c < 3; ++c) {
        const double expected = albedo[c] / kPi * intensity[c] * cosTheta / (r * r);
        EXPECT_NEAR(steady.at(y, x, c), expected, 0.01 * expected) << x << "," << y;
      }
    }
  }
  EXPECT_EQ(result.offAxis.total(), 0.0);
}

TEST(ReferenceClosedFormTest, CameraUnwarpShiftsPeaksByTheCameraDelay) {
  test::PlaneJob s;
  s.job.settings.time = TimeAxis{1.0 / kSpeedOfLight_m_per_s, 0.002 / kSpeedOfLight_m_per_s, 1200};
  s.job.settings.time.camera_unwarp = true;
  const VolumeCollector out = test::renderReference(s.job, directOnly());
  int checked = 0;
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      const double r =
          glm::length(hitOnPlane(s.job.camera(), x, y) - glm::dvec3(s.job.camera().position_world));
      const auto expected = unambiguousBin(s.job.settings.time, r);  // light -> surface only
      if (!expected) continue;
      EXPECT_EQ(peakBin(out.direct, y, x), *expected);
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(ReferenceClosedFormTest, IndexOfRefractionStretchesTheOpticalPath) {
  test::PlaneJob s;
  s.job.settings.time = TimeAxis{3.5 / kSpeedOfLight_m_per_s, 0.002 / kSpeedOfLight_m_per_s, 1500};
  s.job.settings.time.index_of_refraction = 1.33;
  const VolumeCollector out = test::renderReference(s.job, directOnly());
  int checked = 0;
  for (int y = 0; y < s.job.camera().height; y += 3) {
    for (int x = 0; x < s.job.camera().width; x += 3) {
      const double r =
          glm::length(hitOnPlane(s.job.camera(), x, y) - glm::dvec3(s.job.camera().position_world));
      const auto expected = unambiguousBin(s.job.settings.time, 1.33 * 2.0 * r);
      if (!expected) continue;
      EXPECT_EQ(peakBin(out.direct, y, x), *expected);
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(ReferenceClosedFormTest, NoEnergyBeforeTheDirectPath) {
  test::PlaneJob s;
  ReferenceSettings settings;                  // two bounces: a single plane has no indirect light
  settings.pixel_filter = PixelFilter::Point;  // compares pixel centres
  settings.samples_per_pixel = 4;
  settings.threads = 2;
  const VolumeCollector out = test::renderReference(s.job, settings);
  const TransientVolume total = out.total();
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      const double r =
          glm::length(hitOnPlane(s.job.camera(), x, y) - glm::dvec3(s.job.camera().position_world));
      const int firstAllowed = s.job.settings.time.binOf((2.0 * r - 1e-6) / kSpeedOfLight_m_per_s);
      for (int t = 0; t < firstAllowed; ++t) {
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(total.at(y, x, t, c), 0.0f) << x << "," << y << " t=" << t;
      }
    }
  }
  for (float v : out.indirect.values()) ASSERT_EQ(v, 0.0f);
}

TEST(ReferenceClosedFormTest, OccluderCastsAnExactShadow) {
  test::PlaneJob s;
  const float occluderZ = 0.75f, occluderSize = 0.6f;
  test::addQuad(s.scene, glm::vec3(0.0f, 0.0f, occluderZ), glm::vec3(0, 0, 1), occluderSize,
                glm::vec3(0.5f));
  s.job.camera().position_world = {1.2f, 0.3f, 1.6f};
  s.job.camera().look_at_world = {0.0f, 0.0f, 0.0f};
  s.job.light.position_world = {0.0f, 0.0f, 1.5f};
  s.job.settings.time = TimeAxis{0.0, 0.01 / kSpeedOfLight_m_per_s, 1000};
  const Image steady = steadyImage(test::renderReference(s.job, directOnly()).direct);
  int shadowed = 0, lit = 0;
  const glm::dvec3 l(s.job.light.position_world);
  const double half = occluderSize / 2.0;
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      const glm::dvec3 onOccluder = hitOnPlane(s.job.camera(), x, y, occluderZ);
      if (std::abs(onOccluder.x) < half + 0.01 && std::abs(onOccluder.y) < half + 0.01) continue;
      const glm::dvec3 p = hitOnPlane(s.job.camera(), x, y);
      if (std::max(std::abs(p.x), std::abs(p.y)) > 2.9) continue;
      const glm::dvec3 q = l + (p - l) * ((occluderZ - l.z) / (p.z - l.z));
      const double m = std::max(std::abs(q.x), std::abs(q.y));
      // No shadow-map bias: the margin is float rounding only (GL test: 0.03).
      if (m < half - 1e-3) {
        EXPECT_EQ(steady.at(y, x, 0), 0.0f) << "shadowed pixel " << x << "," << y;
        ++shadowed;
      } else if (m > half + 1e-3) {
        EXPECT_GT(steady.at(y, x, 0), 0.0f) << "lit pixel " << x << "," << y;
        ++lit;
      }
    }
  }
  EXPECT_GT(shadowed, 20);
  EXPECT_GT(lit, 200);
}

TEST(ReferenceClosedFormTest, LightInViewLandsInItsPixelAtItsDistance) {
  test::PlaneJob s;
  s.job.light.position_world = {0.2f, 0.1f, 0.5f};  // between the camera and the plane
  s.job.settings.time = TimeAxis{0.0, 0.01 / kSpeedOfLight_m_per_s, 600};
  const VolumeCollector out = test::renderReference(s.job, directOnly());
  const glm::ivec2 xy = s.job.camera().project(s.job.light.position_world);
  ASSERT_GE(xy.x, 0);
  const double d = glm::length(glm::dvec3(s.job.light.position_world) -
                               glm::dvec3(s.job.camera().position_world));
  const int bin = s.job.settings.time.binOf(d / kSpeedOfLight_m_per_s);
  const double solidAngle = s.job.camera().pixelSolidAngle_sr(xy.x, xy.y);
  for (int c = 0; c < 3; ++c) {
    const double expected = s.job.light.intensity_W_per_sr[c] / (d * d * solidAngle);
    EXPECT_NEAR(out.direct.at(xy.y, xy.x, bin, c), expected, 1e-4 * expected);
  }
}

TEST(ReferenceClosedFormTest, LightBehindTheSurfaceIsHidden) {
  test::PlaneJob s;
  s.job.light.position_world = {0.2f, 0.1f, -0.5f};  // behind the plane, inside the view
  ASSERT_GE(s.job.camera().project(s.job.light.position_world).x, 0);
  const VolumeCollector out = test::renderReference(s.job, directOnly());
  // The plane is lit from behind only: two-sided, but facing the camera it
  // turns away from the light, so nothing reaches the camera at all.
  for (float v : out.direct.values()) ASSERT_EQ(v, 0.0f);
}

TEST(ReferenceClosedFormTest, EnergyOffTheAxisIsCountedNotBinned) {
  test::PlaneJob s;
  const Image full = steadyImage(test::renderReference(s.job, directOnly()).direct);
  double total = 0.0;
  for (float v : full.data) total += v;
  // An axis that ends before any light returns.
  s.job.settings.time = TimeAxis{0.0, 0.002 / kSpeedOfLight_m_per_s, 100};
  RenderResult result;
  const VolumeCollector early = test::renderReference(s.job, directOnly(), &result);
  for (float v : early.direct.values()) ASSERT_EQ(v, 0.0f);
  EXPECT_NEAR(result.offAxis.after, total, 1e-6 * total);
  EXPECT_EQ(result.offAxis.before, 0.0);
}

TEST(ReferenceClosedFormTest, LightBeforeTheAxisIsCountedApartFromLightAfterIt) {
  test::PlaneJob s;
  const Image full = steadyImage(test::renderReference(s.job, directOnly()).direct);
  double total = 0.0;
  for (float v : full.data) total += v;
  // An axis that starts after every return: all of the light is early.
  s.job.settings.time = TimeAxis{1e-6, 1e-11, 100};
  RenderResult result;
  test::renderReference(s.job, directOnly(), &result);
  EXPECT_NEAR(result.offAxis.before, total, 1e-6 * total);
  EXPECT_EQ(result.offAxis.after, 0.0);
}

TEST(ReferenceClosedFormTest, SpotLightProfileMatchesTheLightModel) {
  test::PlaneJob s;
  s.job.light.type = Light::Type::Spot;
  s.job.light.direction_world = glm::normalize(glm::vec3(0.2f, 0.1f, -1.5f));
  s.job.light.cone_half_angle_deg = 20.0f;
  s.job.light.cone_falloff_deg = 8.0f;
  const Image steady = steadyImage(test::renderReference(s.job, directOnly()).direct);
  const glm::dvec3 l(s.job.light.position_world);
  int inside = 0, outside = 0;
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      const glm::dvec3 p = hitOnPlane(s.job.camera(), x, y);
      const double r = glm::length(l - p);
      const double profile = s.job.light.angularProfile(glm::vec3((p - l) / r));
      const double expected = 0.5 / kPi * 2.0 * profile * ((l - p).z / r) / (r * r);
      EXPECT_NEAR(steady.at(y, x, 0), expected, 0.01 * expected + 1e-7);
      (profile > 0.0 ? inside : outside)++;
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

}  // namespace
}  // namespace tofsim::reference
