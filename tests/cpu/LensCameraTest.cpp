// A calibrated camera (capture::Camera with a Lens) rendered on the CPU
// backend, against OpenCV's own undistortion (cv::undistortPoints) of each
// pixel centre: a plane facing the camera, lit from the camera, gives every
// pixel the closed-form depth, arrival bin and radiance of OpenCV's ray; and
// the pixel footprint follows the distorted pixel: its arrival-time spread
// equals that of 16 x 16 rays spread over the pixel (OpenCV's pixel, traced
// point by point), where the pinhole's steps would be too narrow at the rim.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <opencv2/calib3d.hpp>
#include <vector>

#include "support/AnalyticScenes.h"
#include "support/CpuRender.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::cpu {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kDistance = 2.0f;  // camera to plane, m
constexpr int kSide = 24;

// Barrel distortion with tangential and thin-prism terms: strong enough that
// a corner pixel's ray is far from the pinhole's (k1 = -0.25 moves the
// corner by ~5 pixels).
capture::Lens testLens() {
  capture::Lens lens;
  lens.fx = 20.0;
  lens.fy = 21.0;
  lens.cx = 11.7;
  lens.cy = 11.2;
  lens.distortion = {-0.25, 0.05, 0.002, -0.003, 0.01, 0, 0, 0, 0.001, 0, -0.001, 0, 0, 0};
  return lens;
}

struct LensScene {
  scene::Scene scene;
  capture::RenderJob job;
  glm::vec3 albedo{0.7f, 0.5f, 0.3f};

  explicit LensScene(bool footprint, int32_t pixelSamples = 1) {
    test::addQuad(scene, glm::vec3(0.0f), glm::vec3(0, 0, 1), 20.0f, albedo);
    job.scene = &scene;
    capture::Camera& c = job.camera();
    c.position_world = {0.0f, 0.0f, kDistance};
    c.look_at_world = {0.0f, 0.0f, 0.0f};
    c.up_world = {0.0f, 1.0f, 0.0f};
    c.width = c.height = kSide;
    c.lens = testLens();
    job.light.position_world = c.position_world;
    job.light.intensity_W_per_sr = glm::vec3(1.0f);
    job.settings.indirect.enabled = false;
    job.settings.pixel_footprint = footprint;
    job.settings.pixel_samples = pixelSamples;
    job.settings.time = TimeAxis{3.9 / kSpeedOfLight_m_per_s, 0.0005 / kSpeedOfLight_m_per_s, 5000};
  }
};

// OpenCV's ideal normalised coordinates of image points (x, y).
std::vector<cv::Point2d> openCvUndistorted(const std::vector<cv::Point2d>& pixels) {
  const capture::Lens l = testLens();
  const cv::Matx33d k(l.fx, 0, l.cx, 0, l.fy, l.cy, 0, 0, 1);
  const std::vector<double> d(l.distortion.begin(), l.distortion.begin() + 12);
  std::vector<cv::Point2d> ideal;
  // Many iterations: OpenCV's default 5 leave ~0.1 px at this distortion.
  cv::undistortPoints(
      pixels, ideal, k, d, cv::noArray(), cv::noArray(),
      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 200, 1e-15));
  return ideal;
}

// The path of light -> plane -> camera along OpenCV's ray of an ideal point.
double roundTrip_m(const cv::Point2d& ideal) {
  return 2.0 * kDistance * std::sqrt(1.0 + ideal.x * ideal.x + ideal.y * ideal.y);
}

TEST(LensCameraTest, EachPixelSeesThePlaneAlongOpenCvsUndistortedRay) {
  const LensScene s(false);
  const test::CpuRender render = test::renderOnCpu(s.job);
  const TransientVolume volume = render.volume.total();
  const TimeAxis& axis = s.job.settings.time;
  std::vector<cv::Point2d> centres;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) centres.emplace_back(x, y);
  }
  const std::vector<cv::Point2d> ideal = openCvUndistorted(centres);
  double worstDepth = 0.0;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const cv::Point2d& p = ideal[static_cast<std::size_t>(y) * kSide + x];
      const double q = std::sqrt(1.0 + p.x * p.x + p.y * p.y);  // |ray| with z = 1
      const double r = kDistance * q;                           // to the plane along the ray
      worstDepth = std::max(worstDepth, std::fabs(render.result.depth_m.at(y, x, 0) - r) / r);
      const int bin = axis.binOf(roundTrip_m(p) / kSpeedOfLight_m_per_s);
      // albedo / pi * I cos / r^2, cos = 1 / q: the radiance the camera sees.
      for (int c = 0; c < 3; ++c) {
        const double expected = s.albedo[c] / kPi / q / (r * r);
        double near = 0.0;
        for (int t = std::max(0, bin - 1); t <= std::min(axis.bins - 1, bin + 1); ++t) {
          near += volume.at(y, x, t, c);
        }
        EXPECT_NEAR(near, expected, 2e-5 * expected) << "pixel " << x << ", " << y;
      }
    }
  }
  // cv::undistortPoints' own residual is ~1e-9 px here: depths agree to float.
  EXPECT_LT(worstDepth, 2e-6);
}

// Mean and standard deviation of a pixel's arrival time (bins of 0.5 mm), channel 0.
struct Spread {
  double mean = 0.0, sd = 0.0;
};
Spread spreadOf(const TransientVolume& v, int y, int x) {
  double w = 0.0, m = 0.0, m2 = 0.0;
  for (int t = 0; t < v.bins(); ++t) {
    const double e = v.at(y, x, t, 0);
    w += e;
    m += e * t;
    m2 += e * t * t;
  }
  m /= w;
  return {m, std::sqrt(std::max(0.0, m2 / w - m * m))};
}

TEST(LensCameraTest, TheFootprintFollowsTheDistortedPixel) {
  const TransientVolume footprint = test::renderOnCpu(LensScene(true).job).volume.total();
  // 16 x 16 point samples over each pixel: the pixel as the lens distorts it.
  const TransientVolume sampled = test::renderOnCpu(LensScene(false, 16).job).volume.total();
  // Relative to each pixel's spread, over the pixels whose spread is first
  // order (sd > 20 bins: all but the centre's few, whose flat patch of plane
  // spreads by its curvature alone, as through a pinhole).
  double worstMean = 0.0, worstSd = 0.0;
  int pixels = 0;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const Spread f = spreadOf(footprint, y, x), b = spreadOf(sampled, y, x);
      if (b.sd <= 20.0) continue;
      ++pixels;
      worstMean = std::max(worstMean, std::fabs(f.mean - b.mean));
      worstSd = std::max(worstSd, std::fabs(f.sd - b.sd) / b.sd);
    }
  }
  EXPECT_GT(pixels, kSide * kSide * 9 / 10);
  // The means differ by the plane's curvature across the pixel, which the
  // first-order footprint leaves out (1.5 bins at the centre, through a
  // pinhole too). The image centre's steps at the rim, where the barrel
  // squeezes more angle into each pixel, would narrow the corners' spread.
  EXPECT_LT(worstMean, 3.0) << "bins";
  EXPECT_LT(worstSd, 0.01);
  std::printf("footprint against 16 x 16 samples: mean within %.2f bins, sd within %.4f\n",
              worstMean, worstSd);
}

}  // namespace
}  // namespace tofsim::cpu
