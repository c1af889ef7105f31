// The colour scale of colour-mapped pictures, read back pixel by pixel: a
// fixed range maps each value to the colour its place in that range says,
// clipped ends get their triangle, signed data a diverging map centred on 0,
// and no-data pixels the documented grey.

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "support/TempDir.h"
#include "tofsim/imaging/Pictures.h"

namespace tofsim {
namespace {

class ColorScaleTest : public test::TempDirTest {
 protected:
  cv::Mat write(const std::string& name, const Image& image, const imaging::ColorScale& scale,
                imaging::ColorScaleUsed* used = nullptr) {
    const imaging::ColorScaleUsed u =
        imaging::writeColormappedPng(dir_ / name, image, "test [m]", scale);
    if (used) *used = u;
    return cv::imread((dir_ / name).string());
  }
};

// 64 x 8, value = column.
Image ramp() {
  Image image(64, 8, 1);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 64; ++x) image.at(y, x, 0) = static_cast<float>(x);
  }
  return image;
}

cv::Vec3b mapped(int index, int code) {
  cv::Mat gray(1, 1, CV_8UC1, cv::Scalar(index)), bgr;
  cv::applyColorMap(gray, bgr, code);
  return bgr.at<cv::Vec3b>(0, 0);
}

// The picture's pixel for image pixel (x, y), from the layout it reports.
cv::Vec3b pixelOf(const cv::Mat& png, const imaging::ColorScaleUsed& u, int x, int y, int w) {
  const int scale = u.imageRect[2] / w;
  return png.at<cv::Vec3b>(u.imageRect[1] + y * scale + scale / 2,
                           u.imageRect[0] + x * scale + scale / 2);
}

// Inside where the triangle beyond the bar's top (or bottom) end is drawn.
cv::Vec3b beyondEnd(const cv::Mat& png, const imaging::ColorScaleUsed& u, bool top) {
  const int x = u.barRect[0] + u.barRect[2] / 2;
  const int y = top ? u.barRect[1] - 5 : u.barRect[1] + u.barRect[3] + 4;
  return png.at<cv::Vec3b>(y, x);
}

const cv::Vec3b kWhite(255, 255, 255);

TEST_F(ColorScaleTest, AFixedRangeIsHonouredAndAClippedEndHasItsTriangle) {
  imaging::ColorScale scale;
  scale.colormap = "viridis";
  scale.range = {{0.0, 100.0}};
  imaging::ColorScaleUsed u;
  const cv::Mat png = write("fixed.png", ramp(), scale, &u);
  EXPECT_FALSE(u.automatic);
  EXPECT_EQ(u.lo, 0.0);
  EXPECT_EQ(u.hi, 100.0);
  EXPECT_FALSE(u.clippedLow || u.clippedHigh);
  for (int x : {0, 17, 40, 63}) {
    EXPECT_EQ(pixelOf(png, u, x, 3, 64),
              mapped(static_cast<int>(std::lround(x / 100.0 * 255.0)), cv::COLORMAP_VIRIDIS))
        << x;
  }
  EXPECT_EQ(beyondEnd(png, u, true), kWhite);  // nothing clipped: no triangles
  EXPECT_EQ(beyondEnd(png, u, false), kWhite);

  // [10, 50]: values on both sides lie outside, drawn in the end colours,
  // and each end of the bar gets a triangle in its colour.
  scale.range = {{10.0, 50.0}};
  const cv::Mat clipped = write("clipped.png", ramp(), scale, &u);
  EXPECT_TRUE(u.clippedLow && u.clippedHigh);
  EXPECT_EQ(pixelOf(clipped, u, 63, 3, 64), mapped(255, cv::COLORMAP_VIRIDIS));
  EXPECT_EQ(pixelOf(clipped, u, 0, 3, 64), mapped(0, cv::COLORMAP_VIRIDIS));
  EXPECT_EQ(pixelOf(clipped, u, 30, 3, 64), mapped(128, cv::COLORMAP_VIRIDIS));
  EXPECT_EQ(beyondEnd(clipped, u, true), mapped(255, cv::COLORMAP_VIRIDIS));
  EXPECT_EQ(beyondEnd(clipped, u, false), mapped(0, cv::COLORMAP_VIRIDIS));
}

TEST_F(ColorScaleTest, TheAutomaticRangeSaysWhereItClips) {
  Image image = ramp();
  image.at(0, 0, 0) = 1e6f;  // one hot pixel: the robust range leaves it out
  imaging::ColorScale scale;
  imaging::ColorScaleUsed u;
  const cv::Mat png = write("auto.png", image, scale, &u);
  EXPECT_TRUE(u.automatic);
  EXPECT_LT(u.hi, 1e6);
  EXPECT_TRUE(u.clippedHigh);
  EXPECT_LT(u.hiPercentile, 100.0);
  EXPECT_EQ(beyondEnd(png, u, true), mapped(255, cv::COLORMAP_TURBO));
}

TEST_F(ColorScaleTest, SignedDataIsCentredOnZeroInADivergingMap) {
  Image image(8, 8, 1);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) image.at(y, x, 0) = static_cast<float>(x) - 2.0f;  // -2 .. 5
  }
  imaging::ColorScale scale;
  scale.diverging = true;
  imaging::ColorScaleUsed u;
  const cv::Mat png = write("signed.png", image, scale, &u);
  EXPECT_EQ(u.lo, -u.hi);
  EXPECT_GT(u.hi, 0.0);
  // 0 (x = 2) is the map's light grey centre; the signs are blue and red.
  const cv::Vec3b zero = pixelOf(png, u, 2, 4, 8);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(zero[c], 221, 2) << c;
  const cv::Vec3b negative = pixelOf(png, u, 0, 4, 8), positive = pixelOf(png, u, 7, 4, 8);
  EXPECT_GT(negative[0], negative[2]);  // BGR: more blue than red
  EXPECT_GT(positive[2], positive[0]);
}

TEST_F(ColorScaleTest, NoDataIsGreyAndTheRangeSpansTheSurfacesOnly) {
  Image depth(16, 16, 1);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) depth.at(y, x, 0) = x < 8 ? 0.0f : 2.0f + 0.1f * float(y);
  }
  depth.at(15, 15, 0) = NAN;
  imaging::ColorScale scale;
  scale.nonPositiveIsNoData = true;
  scale.noDataLabel = "no surface";
  imaging::ColorScaleUsed u;
  const cv::Mat png = write("depth.png", depth, scale, &u);
  EXPECT_GE(u.lo, 2.0);  // not from 0: the background is not a depth
  EXPECT_EQ(u.noDataPixels, 8 * 16 + 1);
  const cv::Vec3b grey(imaging::kNoDataGrey, imaging::kNoDataGrey, imaging::kNoDataGrey);
  EXPECT_EQ(pixelOf(png, u, 0, 0, 16), grey);
  EXPECT_EQ(pixelOf(png, u, 15, 15, 16), grey);
  EXPECT_NE(pixelOf(png, u, 9, 3, 16), grey);
}

}  // namespace
}  // namespace tofsim
