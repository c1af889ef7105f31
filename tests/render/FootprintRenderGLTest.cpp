// The pixel footprint through the whole IR driver, on both backends, against
// closed forms: a plane seen at 10 degrees (pixels spanning tens of bins)
// against a fine sub-pixel quadrature of the exact direct term, and a plane
// seen head-on, where the footprint must keep point sampling's peak bin and
// energy (it spreads only time; radiance is taken at the pixel centre).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "support/AnalyticScenes.h"
#include "support/ClosedForm.h"
#include "support/HistogramMetrics.h"
#include "support/TestBackends.h"
#include "support/TestJobs.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::render {
namespace {

using namespace capture;

constexpr double kPi = 3.14159265358979323846;
constexpr float kAlbedo = 0.6f;
constexpr float kIntensity = 5.0f;

class FootprintRenderGLTest : public test::BackendTest {
 protected:
  VolumeCollector renderJob(const RenderJob& job) const {
    VolumeCollector collector(job.camera().width, job.camera().height, job.settings.time, 3);
    renderer()->render(job, collector);
    return collector;
  }
};

// A 40 m plane z = 0 seen from 0.5 m above at 10 degrees below the horizon,
// the light at the camera: the floor of the issue, at 64 x 64 pixels (each
// spanning up to ~80 bins of 20 ps).
struct GrazingPlane {
  scene::Scene scene = test::makePlane(40.0f, glm::vec3(kAlbedo));
  RenderJob job;
  GrazingPlane() {
    const double grazing = 10.0 * kPi / 180.0;
    job.scene = &scene;
    job.camera().position_world = {0.0f, 0.0f, 0.5f};
    job.camera().look_at_world =
        job.camera().position_world + glm::vec3(0.0f, static_cast<float>(std::cos(grazing)),
                                                -static_cast<float>(std::sin(grazing)));
    job.camera().up_world = {0.0f, 0.0f, 1.0f};
    job.camera().fov_y_deg = 40.0f;
    job.camera().width = job.camera().height = 64;
    job.light.position_world = job.camera().position_world;
    job.light.intensity_W_per_sr = glm::vec3(kIntensity);
    job.settings.indirect.enabled = false;
    job.settings.shadow_map_resolution = 512;
    job.settings.time = TimeAxis{1.5 / kSpeedOfLight_m_per_s, 20e-12, 1200};  // 1.5 .. 8.7 m
  }
};

// Histogram (channel 0) of pixel (px, py) from sub x sub sub-points of the
// exact direct term: path 2 |x - c|, radiance rho / pi * I * cos / r^2; empty
// when a corner of the pixel misses the plane or leaves the axis.
std::vector<double> quadrature(const RenderJob& job, int px, int py, int sub) {
  const TimeAxis& axis = job.settings.time;
  const glm::dvec3 c(job.camera().position_world);
  const auto hit = [&](glm::vec2 offset, glm::dvec3& x) {
    const glm::dvec3 d(job.camera().pixelDirection(px, py, offset));
    if (d.z >= 0.0) return false;
    x = c + d * (-c.z / d.z);
    const double f =
        (2.0 * glm::length(x - c) / kSpeedOfLight_m_per_s - axis.start_s) / axis.bin_width_s;
    return f > 1.0 && f < axis.bins - 1.0 && std::abs(x.x) < 19.0 && std::abs(x.y) < 19.0;
  };
  glm::dvec3 x;
  for (int corner = 0; corner < 4; ++corner) {
    if (!hit(glm::vec2(corner % 2 - 0.5f, corner / 2 - 0.5f), x)) return {};
  }
  std::vector<double> h(axis.bins, 0.0);
  for (int i = 0; i < sub; ++i) {
    for (int j = 0; j < sub; ++j) {
      hit(glm::vec2((i + 0.5f) / sub - 0.5f, (j + 0.5f) / sub - 0.5f), x);
      const glm::dvec3 toLight = c - x;
      const double r = glm::length(toLight);
      const double radiance = kAlbedo / kPi * kIntensity * (toLight.z / r) / (r * r);
      const double f = (2.0 * r / kSpeedOfLight_m_per_s - axis.start_s) / axis.bin_width_s;
      h[static_cast<std::size_t>(std::floor(f))] += radiance / (double(sub) * sub);
    }
  }
  return h;
}

std::vector<double> pixelHistogram(const TransientVolume& v, int px, int py) {
  std::vector<double> h(v.bins());
  for (int t = 0; t < v.bins(); ++t) h[t] = v.at(py, px, t, 0);
  return h;
}

TEST_P(FootprintRenderGLTest, GrazingPlaneMatchesASubPixelQuadratureOfTheDirectTerm) {
  GrazingPlane s;
  const VolumeCollector footprint = renderJob(s.job);
  s.job.settings.pixel_footprint = false;
  const VolumeCollector point = renderJob(s.job);
  std::vector<double> l1s, pointL1s, energyErrors;
  for (int py = 32; py < 64; py += 4) {
    for (int px = 1; px < 64; px += 6) {
      const std::vector<double> truth = quadrature(s.job, px, py, 200);
      if (truth.empty()) continue;
      const std::vector<double> h = pixelHistogram(footprint.direct, px, py);
      l1s.push_back(test::normalisedL1(h, truth));
      pointL1s.push_back(test::normalisedL1(pixelHistogram(point.direct, px, py), truth));
      energyErrors.push_back(std::abs(test::histogramSum(h) / test::histogramSum(truth) - 1.0));
    }
  }
  ASSERT_GE(l1s.size(), 40u);
  const double worstEnergy = *std::max_element(energyErrors.begin(), energyErrors.end());
  std::printf(
      "%zu pixels: footprint median L1 %.4f (max %.4f), point pixels median L1 %.3f; "
      "energy within %.3f%%\n",
      l1s.size(), test::median(l1s), *std::max_element(l1s.begin(), l1s.end()),
      test::median(pointL1s), 100.0 * worstEnergy);
  // The first-order trapezoid's own error (tests/physics: median 0.02-0.03)
  // plus the renderer's float surface point.
  EXPECT_LT(test::median(l1s), 0.06);
  EXPECT_LT(worstEnergy, 0.02);
  EXPECT_GT(test::median(pointL1s), 1.5);  // what the footprint fixes: almost disjoint
}

TEST_P(FootprintRenderGLTest, HeadOnPlaneKeepsThePeakBinAndPointSamplingsEnergy) {
  test::PlaneJob s;
  s.job.settings.indirect.enabled = false;
  // Straight down, the centre's path (3.0026 m) mid-bin.
  s.job.camera().position_world = s.job.light.position_world = {0.0f, 0.0f, 1.5013f};
  s.job.camera().look_at_world = {0.0f, 0.0f, 0.0f};
  s.job.camera().width = 41;
  s.job.camera().height = 31;
  s.job.camera().fov_y_deg = 40.0f;
  const VolumeCollector footprint = renderJob(s.job);
  s.job.settings.pixel_footprint = false;
  const VolumeCollector point = renderJob(s.job);
  // The centre pixel: the path is stationary there, its kernel within a bin.
  const glm::dvec3 p = test::hitOnPlane(s.job.camera(), 20, 15);
  const double r = glm::length(p - glm::dvec3(s.job.camera().position_world));
  ASSERT_TRUE(test::unambiguousBin(s.job.settings.time, 2.0 * r));
  EXPECT_EQ(test::peakBin(footprint.direct, 15, 20),
            *test::unambiguousBin(s.job.settings.time, 2.0 * r));
  // Energy per pixel: the same centre radiance, only spread in time.
  const Image a = steadyImage(footprint.direct), b = steadyImage(point.direct);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.data.size(); ++i) {
    ASSERT_GT(b.data[i], 0.0f);
    worst = std::max(worst, std::abs(double(a.data[i]) / b.data[i] - 1.0));
  }
  // Float rounding of the bin masses (measured 1.1e-5 at worst).
  EXPECT_LT(worst, 5e-5);
  // And the footprint does spread: off the centre, pixels cover several bins.
  int spread = 0;
  for (int t = 0; t < footprint.direct.bins(); ++t) spread += footprint.direct.at(0, 0, t, 0) > 0;
  EXPECT_GE(spread, 3);
}

TEST_P(FootprintRenderGLTest, PointPixelsPutAllOfAPixelsLightInOneBin) {
  test::PlaneJob s;
  s.job.settings.indirect.enabled = false;
  s.job.settings.pixel_footprint = false;
  const VolumeCollector out = renderJob(s.job);
  for (int y = 0; y < s.job.camera().height; ++y) {
    for (int x = 0; x < s.job.camera().width; ++x) {
      int lit = 0;
      for (int t = 0; t < out.direct.bins(); ++t) lit += out.direct.at(y, x, t, 0) > 0;
      ASSERT_LE(lit, 1) << x << "," << y;
    }
  }
}

TEST_P(FootprintRenderGLTest, SubPixelSamplesKeepTheQuadraturesShapeAndEnergy) {
  // pixel_samples: the footprint shrinks to the sub-pixel, the energy of a
  // pixel is the mean of its samples'. On the grazing plane both the 1 and
  // the 3 x 3 render must match the quadrature; 3 x 3 at least as well.
  GrazingPlane s;
  s.job.camera().width = s.job.camera().height = 24;
  s.job.settings.pixel_samples = 3;
  const VolumeCollector three = renderJob(s.job);
  s.job.settings.pixel_samples = 1;
  const VolumeCollector one = renderJob(s.job);
  std::vector<double> l1Three, l1One;
  for (int py = 12; py < 24; py += 2) {
    for (int px = 1; px < 24; px += 3) {
      const std::vector<double> truth = quadrature(s.job, px, py, 120);
      if (truth.empty()) continue;
      l1Three.push_back(test::normalisedL1(pixelHistogram(three.direct, px, py), truth));
      l1One.push_back(test::normalisedL1(pixelHistogram(one.direct, px, py), truth));
      EXPECT_NEAR(
          test::histogramSum(pixelHistogram(three.direct, px, py)) / test::histogramSum(truth), 1.0,
          0.01);
    }
  }
  ASSERT_GE(l1Three.size(), 20u);
  std::printf("median L1: 1 sample %.4f, 3 x 3 samples %.4f\n", test::median(l1One),
              test::median(l1Three));
  EXPECT_LT(test::median(l1Three), 0.06);
  EXPECT_LE(test::median(l1Three), test::median(l1One) * 1.05);
}

TOFSIM_ON_BOTH_BACKENDS(FootprintRenderGLTest);

}  // namespace
}  // namespace tofsim::render
