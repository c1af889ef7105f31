// capture::vignettingGains: cos^4 of each pixel's ray angle to the optical
// axis, through a pinhole (closed form) and through a lens (the angle of
// OpenCV's undistorted ray, cv::undistortPoints); a map passes through.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <vector>

#include "tofsim/capture/Vignetting.h"

namespace tofsim::capture {
namespace {

Camera camera(int32_t w, int32_t h) {
  Camera c;
  c.position_world = {0.3f, -0.2f, 1.0f};
  c.look_at_world = {0.0f, 0.5f, -2.0f};
  c.width = w;
  c.height = h;
  c.fov_y_deg = 70.0f;
  return c;
}

TEST(VignettingTest, PinholeGainIsCos4OfThePixelsAngle) {
  const Camera c = camera(32, 24);
  const std::vector<float> g = vignettingGains(c, {Vignetting::Kind::Cos4});
  ASSERT_EQ(g.size(), 32u * 24u);
  const double tanHalf = std::tan(35.0 * M_PI / 180.0);
  for (int y = 0; y < 24; ++y) {
    for (int x = 0; x < 32; ++x) {
      // The image plane at unit distance: (u, v), cos = 1 / sqrt(1 + u^2 + v^2).
      const double u = (2.0 * (x + 0.5) / 32.0 - 1.0) * tanHalf * 32.0 / 24.0;
      const double v = (1.0 - 2.0 * (y + 0.5) / 24.0) * tanHalf;
      const double cos2 = 1.0 / (1.0 + u * u + v * v);
      EXPECT_NEAR(g[static_cast<std::size_t>(y) * 32 + x], cos2 * cos2, 2e-6) << x << ", " << y;
    }
  }
  EXPECT_TRUE(vignettingGains(c, {}).empty());
}

TEST(VignettingTest, LensGainIsCos4OfOpenCvsUndistortedRay) {
  Camera c = camera(40, 30);
  Lens lens;
  lens.fx = 30.0;
  lens.fy = 31.0;
  lens.cx = 19.2;
  lens.cy = 14.9;
  lens.distortion = {-0.28, 0.07, 0.002, -0.001, 0.0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  c.lens = lens;
  const std::vector<float> g = vignettingGains(c, {Vignetting::Kind::Cos4});
  std::vector<cv::Point2d> pixels, ideal;
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 40; ++x) pixels.emplace_back(x, y);
  }
  const cv::Matx33d k(lens.fx, 0, lens.cx, 0, lens.fy, lens.cy, 0, 0, 1);
  const std::vector<double> d(lens.distortion.begin(), lens.distortion.begin() + 5);
  cv::undistortPoints(
      pixels, ideal, k, d, cv::noArray(), cv::noArray(),
      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 200, 1e-15));
  double rim = 1.0;
  for (std::size_t i = 0; i < ideal.size(); ++i) {
    const double cos2 = 1.0 / (1.0 + ideal[i].x * ideal[i].x + ideal[i].y * ideal[i].y);
    EXPECT_NEAR(g[i], cos2 * cos2, 2e-6) << i;
    rim = std::min(rim, cos2 * cos2);
  }
  EXPECT_LT(rim, 0.5);  // the corners' fall-off is large: the test can tell
}

TEST(VignettingTest, AMapIsTheGains) {
  const Camera c = camera(3, 2);
  Vignetting v{Vignetting::Kind::Map, {1.0f, 0.9f, 0.8f, 0.7f, 0.6f, 0.5f}, 3, 2, "flat.npy"};
  EXPECT_EQ(vignettingGains(c, v), v.map);
}

}  // namespace
}  // namespace tofsim::capture
