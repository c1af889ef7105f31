// An NLOS capture's pictures (issue 44, item 11): the projections of H they
// draw put each bin's light where the wall and the time axis say: the
// steady image at (the wall's y from the top, x), the x-t and y-t images at
// (bin, x) and (bin, y), laser points summed, and long axes summed into at
// most kNlosPictureRows rows.

#include <gtest/gtest.h>

#include <numeric>

#include "NlosPictures.h"

namespace tofsim::pipeline {
namespace {

NlosVolume volumeOf(std::vector<std::size_t> shape) {
  NlosVolume v;
  v.shape = std::move(shape);
  v.axis.bins = static_cast<int32_t>(v.shape[0]);
  v.axis.bin_width_s = 1e-11;
  v.H.assign(std::accumulate(v.shape.begin(), v.shape.end(), std::size_t{1},
                             std::multiplies<std::size_t>()),
             0.0f);
  return v;
}

TEST(NlosPicturesTest, EachProjectionPutsTheLightWhereTheWallAndTimeSay) {
  // H[t][sx][sy] of 5 bins, 3 x 4 points: 2 at (t 3, sx 1, sy 2).
  NlosVolume v = volumeOf({5, 3, 4});
  v.H[(3 * 3 + 1) * 4 + 2] = 2.0f;
  const std::vector<Image> p = nlosProjections(v);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].width, 3);
  EXPECT_EQ(p[0].height, 4);
  EXPECT_EQ(p[0].at(4 - 1 - 2, 1, 0), 2.0f);  // the wall's +y up
  EXPECT_EQ(p[1].width, 3);
  EXPECT_EQ(p[1].height, 5);
  EXPECT_EQ(p[1].at(3, 1, 0), 2.0f);
  EXPECT_EQ(p[2].width, 4);
  EXPECT_EQ(p[2].at(3, 2, 0), 2.0f);
  for (const Image& image : p) {
    EXPECT_EQ(std::accumulate(image.data.begin(), image.data.end(), 0.0f), 2.0f);
  }
}

TEST(NlosPicturesTest, LaserPointsAndLongAxesAreSummed) {
  // Exhaustive: H[t][lx][ly][sx][sy], 2 x 1 laser points; 5000 bins become
  // rows of 3 bins (1667 rows).
  NlosVolume v = volumeOf({5000, 2, 1, 3, 2});
  const auto at = [](std::size_t t, std::size_t lx, std::size_t sx, std::size_t sy) {
    return (((t * 2 + lx) * 1 + 0) * 3 + sx) * 2 + sy;
  };
  v.H[at(4000, 0, 2, 1)] = 1.0f;  // bins 3999 .. 4001 make row 1333
  v.H[at(4001, 1, 2, 1)] = 3.0f;
  EXPECT_EQ(nlosPictureBinsPerRow(5000), 3u);
  const std::vector<Image> p = nlosProjections(v);
  EXPECT_EQ(p[0].at(0, 2, 0), 4.0f);
  EXPECT_EQ(p[1].height, 1667);
  EXPECT_EQ(p[1].at(1333, 2, 0), 4.0f);
  EXPECT_EQ(p[2].at(1333, 1, 0), 4.0f);
}

}  // namespace
}  // namespace tofsim::pipeline
