// The viewer's packing and downsampling (apps/viewer/src): halves rounded to
// nearest even, base64 as RFC 4648 writes it, plans that fit the page's
// budget whatever the volume, block means over partial blocks and NaN.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "Downsample.h"
#include "PackedArray.h"
#include "ViewerBudget.h"

namespace tofsim::viewer {
namespace {

TEST(ViewerPackingTest, HalvesRoundToNearestEven) {
  EXPECT_EQ(toHalf(1.0f), 0x3c00);
  EXPECT_EQ(toHalf(-2.0f), 0xc000);
  EXPECT_EQ(toHalf(65504.0f), 0x7bff);                      // the largest half
  EXPECT_EQ(toHalf(65519.0f), 0x7bff);                      // rounds down to it
  EXPECT_EQ(toHalf(65520.0f), 0x7c00);                      // rounds to infinity
  EXPECT_EQ(toHalf(1.0f + std::ldexp(1.0f, -11)), 0x3c00);  // a tie: to even
  EXPECT_EQ(toHalf(1.0f + 3 * std::ldexp(1.0f, -11)), 0x3c02);
  EXPECT_EQ(toHalf(std::ldexp(1.0f, -14)), 0x0400);  // the smallest normal
  EXPECT_EQ(toHalf(std::ldexp(1.0f, -24)), 0x0001);  // the smallest subnormal
  EXPECT_EQ(toHalf(std::ldexp(1.0f, -26)), 0x0000);
  EXPECT_EQ(toHalf(std::ldexp(3.0f, -25)), 0x0002);  // 1.5 steps: a tie, to even
  EXPECT_EQ(toHalf(std::numeric_limits<float>::quiet_NaN()) & 0x7e00, 0x7e00);
}

TEST(ViewerPackingTest, Base64IsRfc4648s) {
  EXPECT_EQ(base64("Man", 3), "TWFu");
  EXPECT_EQ(base64("Ma", 2), "TWE=");
  EXPECT_EQ(base64("M", 1), "TQ==");
  EXPECT_EQ(base64("", 0), "");
}

TEST(ViewerPackingTest, Uint16MapsKeepNaNAndTheirRange) {
  const nlohmann::json p = packUint16({2.0f, std::nanf(""), 4.0f, 3.0f});
  EXPECT_EQ(p["lo"], 2.0);
  EXPECT_EQ(p["hi"], 4.0);
  // 0, 65535 (NaN), 65534, 32767: little-endian words.
  const unsigned char bytes[] = {0x00, 0x00, 0xff, 0xff, 0xfe, 0xff, 0xff, 0x7f};
  EXPECT_EQ(p["data"], base64(bytes, sizeof bytes));
}

TEST(ViewerDownsampleTest, PlansFitTheBudgetWhateverTheVolume) {
  const Reduction none = planReduction(10, 12, 64, 3, kVolumeValues);
  EXPECT_EQ(none.pixelBlock, 1u);
  EXPECT_EQ(none.binRun, 1u);
  // cornell_box.yaml: 128 x 128 x 640 x 3 = 31.5 Mi values -> bins 2, pixels 2.
  const Reduction cornell = planReduction(128, 128, 640, 3, kVolumeValues);
  EXPECT_EQ(cornell.binRun, 2u);
  EXPECT_EQ(cornell.pixelBlock, 2u);
  for (const auto& [h, w, t, c] : std::vector<std::array<std::size_t, 4>>{
           {2048, 2048, 4096, 3}, {1, 1, 1u << 30, 1}, {16384, 16384, 1, 4}, {7, 5, 3, 300000}}) {
    const Reduction r = planReduction(h, w, t, c, kVolumeValues);
    EXPECT_LE(
        reducedSize(h, r.pixelBlock) * reducedSize(w, r.pixelBlock) * reducedSize(t, r.binRun) * c,
        std::max<std::size_t>(kVolumeValues, c))
        << h << " x " << w << " x " << t << " x " << c;
  }
  EXPECT_EQ(planPixelBlock(512, 512, 1, kMapValues), 1u);
  EXPECT_EQ(planPixelBlock(513, 512, 1, kMapValues), 2u);
}

TEST(ViewerDownsampleTest, BlockMeansAverageWhatEachBlockHolds) {
  // 3 x 3, blocks of 2: a full block, two partial ones and a corner; a NaN
  // is left out of its block's mean.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> image = {1, 2, 3, 4, nan, 6, 7, 8, 9};
  const std::vector<float> mean = blockMean(image, 3, 3, 1, 2);
  ASSERT_EQ(mean.size(), 4u);
  EXPECT_FLOAT_EQ(mean[0], (1 + 2 + 4) / 3.0f);
  EXPECT_FLOAT_EQ(mean[1], (3 + 6) / 2.0f);
  EXPECT_FLOAT_EQ(mean[2], (7 + 8) / 2.0f);
  EXPECT_FLOAT_EQ(mean[3], 9.0f);
  EXPECT_TRUE(std::isnan(blockMean({nan}, 1, 1, 1, 2)[0]));
}

}  // namespace
}  // namespace tofsim::viewer
