// The lens model against OpenCV's own: distortion equals cv::projectPoints,
// undistortion cv::undistortPoints, for 4, 5, 8, 12 and 14 coefficients, and
// our undistort-distort round trip is exact to 1e-10 px.
#include "tofsim/capture/Lens.h"

#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>
#include <string>
#include <vector>

#include "tofsim/util/Error.h"

namespace tofsim::capture {
namespace {

Lens kinectLikeLens(int coefficients) {
  Lens lens;
  lens.fx = 365.5;
  lens.fy = 366.1;
  lens.cx = 257.3;
  lens.cy = 206.8;
  // A distorted wide lens (k1, k3 Kinect v2-like; its k2 of -0.27 without
  // k3 folds the image corners), with thin-prism and tilt terms small enough
  // to stay invertible over the image.
  const std::array<double, 14> all = {0.0912, -0.1216, 0.0011, -0.0008, 0.0957, 0.012, -0.004,
                                      0.002,  0.0013,  -0.0006, 0.0009,  0.0004, 0.004, -0.003};
  for (int i = 0; i < coefficients; ++i) lens.distortion[i] = all[i];
  return lens;
}

cv::Mat cameraMatrix(const Lens& lens) {
  return (cv::Mat_<double>(3, 3) << lens.fx, 0, lens.cx, 0, lens.fy, lens.cy, 0, 0, 1);
}

cv::Mat distortionOf(const Lens& lens, int coefficients) {
  cv::Mat d(1, coefficients, CV_64F);
  for (int i = 0; i < coefficients; ++i) d.at<double>(0, i) = lens.distortion[i];
  return d;
}

class LensTest : public ::testing::TestWithParam<int> {};

TEST_P(LensTest, DistortionIsOpenCvsProjectPoints) {
  const int k = GetParam();
  const Lens lens = kinectLikeLens(k);
  std::vector<cv::Point3d> points;
  for (double y = -0.55; y <= 0.55; y += 0.05) {
    for (double x = -0.7; x <= 0.7; x += 0.05) points.emplace_back(x, y, 1.0);
  }
  std::vector<cv::Point2d> projected;
  cv::projectPoints(points, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), cameraMatrix(lens),
                    distortionOf(lens, k), projected);
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::dvec2 ours =
        normalisedToPixel(lens, distortNormalised(lens, {points[i].x, points[i].y}));
    worst = std::max({worst, std::fabs(ours.x - projected[i].x), std::fabs(ours.y - projected[i].y)});
  }
  EXPECT_LT(worst, 1e-9) << k << " coefficients: worst difference in pixels";
}

TEST_P(LensTest, UndistortionMatchesOpenCvAndRoundTrips) {
  const int k = GetParam();
  const Lens lens = kinectLikeLens(k);
  std::vector<cv::Point2d> pixels;
  for (int y = 0; y <= 424; y += 8) {
    for (int x = 0; x <= 512; x += 8) pixels.emplace_back(x, y);
  }
  std::vector<cv::Point2d> theirs;
  // OpenCV iterates a fixed-point scheme; ask it for many iterations so that
  // the comparison measures our model, not its stopping rule.
  cv::undistortPoints(pixels, theirs, cameraMatrix(lens), distortionOf(lens, k), cv::noArray(),
                      cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 200, 1e-15));
  double worstOpenCv = 0.0, worstRoundTrip = 0.0;
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    glm::dvec2 ideal;
    const glm::dvec2 pixel(pixels[i].x, pixels[i].y);
    ASSERT_TRUE(undistortNormalised(lens, pixelToNormalised(lens, pixel), ideal)) << pixel.x << ", " << pixel.y;
    const glm::dvec2 theirsPx = normalisedToPixel(lens, {theirs[i].x, theirs[i].y});
    const glm::dvec2 oursPx = normalisedToPixel(lens, ideal);
    worstOpenCv = std::max({worstOpenCv, std::fabs(oursPx.x - theirsPx.x), std::fabs(oursPx.y - theirsPx.y)});
    const glm::dvec2 back = normalisedToPixel(lens, distortNormalised(lens, ideal));
    worstRoundTrip = std::max({worstRoundTrip, std::fabs(back.x - pixel.x), std::fabs(back.y - pixel.y)});
  }
  // The bounds: 0.01 px against OpenCV, 1e-10 px round trip.
  EXPECT_LT(worstOpenCv, 0.01) << k << " coefficients";
  EXPECT_LT(worstRoundTrip, 1e-10) << k << " coefficients";
}

INSTANTIATE_TEST_SUITE_P(Coefficients, LensTest, ::testing::Values(4, 5, 8, 12, 14));

TEST(LensJacobianTest, MatchesFiniteDifferencesOfTheModel) {
  const Lens lens = kinectLikeLens(14);
  const glm::dvec2 p(0.31, -0.22);
  const glm::dmat2 J = distortionJacobian(lens, p);
  const double h = 1e-4;
  // A coarser, one-sided difference: agreement to O(h) says the columns are
  // d/dx and d/dy in the right order.
  const glm::dvec2 dx = (distortNormalised(lens, p + glm::dvec2(h, 0)) - distortNormalised(lens, p)) / h;
  const glm::dvec2 dy = (distortNormalised(lens, p + glm::dvec2(0, h)) - distortNormalised(lens, p)) / h;
  EXPECT_NEAR(J[0].x, dx.x, 1e-3);
  EXPECT_NEAR(J[0].y, dx.y, 1e-3);
  EXPECT_NEAR(J[1].x, dy.x, 1e-3);
  EXPECT_NEAR(J[1].y, dy.y, 1e-3);
}

TEST(LensUndistortTest, AFoldedLensIsNotInverted) {
  Lens lens;
  lens.distortion[0] = -1.5;  // r (1 - 1.5 r^2) folds back at r = 0.47
  glm::dvec2 ideal;
  EXPECT_FALSE(undistortNormalised(lens, {0.5, 0.0}, ideal));  // beyond the fold's maximum 0.27
}

TEST(LensInvertibleTest, TheKinectLikeLensPassesAndAFoldingOneIsNamed) {
  EXPECT_NO_THROW(checkLensInvertible(kinectLikeLens(14), 512, 424));
  // Kinect v2's k1, k2 without its k3: r (1 + k1 r^2 + k2 r^4) peaks at
  // r = 0.98, inside the image's corners (r = 0.89 distorted there).
  Lens folded = kinectLikeLens(4);
  folded.distortion[1] = -0.2716;
  try {
    checkLensInvertible(folded, 512, 424);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pixel (0, 0)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tofsim::capture
