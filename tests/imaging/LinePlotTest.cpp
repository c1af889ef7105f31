// The PNG writers of apps/imaging: files of the requested size that OpenCV
// reads back, with the curves and colour bars actually drawn.

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgcodecs.hpp>

#include "support/TempDir.h"
#include "tofsim/imaging/LinePlot.h"
#include "tofsim/imaging/Pictures.h"

namespace tofsim {
namespace {

class ImagingTest : public test::TempDirTest {};

// Pixels that are neither white nor grey: drawn by a curve or a colormap.
int colouredPixels(const cv::Mat& bgr) {
  int n = 0;
  for (int y = 0; y < bgr.rows; ++y) {
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
      const int spread = std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]});
      if (spread > 60) ++n;
    }
  }
  return n;
}

TEST_F(ImagingTest, LinePlotHasRequestedSizeAndCurves) {
  imaging::LinePlot plot;
  for (int s = 0; s < 3; ++s) {
    std::vector<float> curve;
    for (int i = 0; i < 200; ++i)
      curve.push_back(100.0f * std::exp(-0.5f * std::pow((i - 50 - 40 * s) / 8.0f, 2.0f)));
    plot.series.push_back(curve);
    plot.labels.push_back("pixel " + std::to_string(s));
  }
  plot.x0 = 5.0;
  plot.dx = 0.01;
  plot.xUnit = "ns";
  plot.yLabel = "counts";
  plot.title = "test histograms";
  plot.width_px = 640;
  plot.height_px = 360;
  const auto path = dir_ / "plot.png";
  imaging::writeLinePlotPng(path, plot);
  const cv::Mat image = cv::imread(path.string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 640);
  EXPECT_EQ(image.rows, 360);
  EXPECT_GT(colouredPixels(image), 300);
  // Atomic writer: no temporary left beside the file.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_), {}), 1);
}

TEST_F(ImagingTest, LinePlotOfFlatOrEmptyDataStillWrites) {
  imaging::LinePlot plot;
  plot.series = {std::vector<float>(10, 0.0f)};
  imaging::writeLinePlotPng(dir_ / "flat.png", plot);
  plot.series.clear();
  imaging::writeLinePlotPng(dir_ / "empty.png", plot);
  EXPECT_FALSE(cv::imread((dir_ / "flat.png").string()).empty());
  EXPECT_FALSE(cv::imread((dir_ / "empty.png").string()).empty());
}

imaging::ColorScale named(const char* colormap) {
  imaging::ColorScale scale;
  scale.colormap = colormap;
  return scale;
}

TEST_F(ImagingTest, ColormappedPngUsesTheNamedColormap) {
  Image ramp(64, 8, 1);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 64; ++x) ramp.at(y, x, 0) = static_cast<float>(x);
  }
  ramp.at(0, 0, 0) = NAN;
  imaging::writeColormappedPng(dir_ / "viridis.png", ramp, "ramp [m]", named("viridis"));
  imaging::writeColormappedPng(dir_ / "unknown.png", ramp, "ramp [m]", named("no-such-map"));
  imaging::writeColormappedPng(dir_ / "turbo.png", ramp, "ramp [m]", named("turbo"));
  const cv::Mat viridis = cv::imread((dir_ / "viridis.png").string());
  const cv::Mat unknown = cv::imread((dir_ / "unknown.png").string());
  const cv::Mat turbo = cv::imread((dir_ / "turbo.png").string());
  ASSERT_FALSE(viridis.empty());
  EXPECT_GT(colouredPixels(viridis), 64 * 8);
  // Unknown names fall back to turbo: the same picture.
  ASSERT_EQ(unknown.size(), turbo.size());
  EXPECT_EQ(cv::norm(unknown, turbo, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(viridis, turbo, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace tofsim
