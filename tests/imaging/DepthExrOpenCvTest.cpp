// depth.exr as OpenCV reads it (the library behind Python's cv2.imread):
// OpenCV takes only R, G, B or Y and ignores a channel named Z, so a depth
// written as Z alone reads as zeros. writeDepthExr's Y channel is seen.

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "support/TempDir.h"
#include "tofsim/io/DepthExr.h"
#include "tofsim/io/Exr.h"

namespace tofsim {
namespace {

class DepthExrOpenCvTest : public test::TempDirTest {};

Image ramp(int w, int h) {
  Image depth(w, h, 1);
  for (std::size_t i = 0; i < depth.data.size(); ++i) depth.data[i] = 0.8f + 0.01f * float(i);
  return depth;
}

TEST_F(DepthExrOpenCvTest, OpenCvReadsTheDepthInMetres) {
  const Image depth = ramp(7, 5);
  io::writeDepthExr(dir_ / "depth.exr", depth);
  const cv::Mat m = cv::imread((dir_ / "depth.exr").string(), cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(m.empty());
  ASSERT_EQ(m.type(), CV_32FC1);
  ASSERT_EQ(m.cols, 7);
  ASSERT_EQ(m.rows, 5);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 7; ++x) EXPECT_EQ(m.at<float>(y, x), depth.at(y, x, 0)) << x << "," << y;
  }
}

TEST_F(DepthExrOpenCvTest, AChannelNamedZAloneReadsAsZerosInOpenCv) {
  // Why depth.exr carries Y: the form older versions wrote.
  io::writeExr(dir_ / "z.exr", ramp(4, 3), {"Z"});
  const cv::Mat m = cv::imread((dir_ / "z.exr").string(), cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(m.empty());
  EXPECT_EQ(cv::countNonZero(m), 0);
}

}  // namespace
}  // namespace tofsim
