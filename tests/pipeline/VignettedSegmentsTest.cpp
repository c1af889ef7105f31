// pipeline::VignettedSegments: every component of a segment times its
// pixel's gain, and the indirect light still the float sum of its bounces.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "tofsim/pipeline/VignettedSegments.h"

namespace tofsim::pipeline {
namespace {

struct Collect : capture::SegmentSink {
  std::vector<std::vector<float>> components;
  std::vector<std::string_view> names;
  std::size_t first = 0, count = 0;
  void consume(const capture::Segment& s) override {
    first = s.firstPixel;
    count = s.pixelCount;
    components.clear();
    names.clear();
    const std::size_t floats = s.pixelCount * 2 * capture::kChannels;
    for (const auto& c : s.components) {
      names.push_back(c.name);
      components.emplace_back(c.values, c.values + floats);
    }
  }
};

TEST(VignettedSegmentsTest, ScalesEachPixelAndKeepsTheBouncesSum) {
  constexpr int32_t kBins = 2;
  const std::vector<float> gains = {1.0f, 0.5f, 0.3f, 0.7f};
  Collect out;
  VignettedSegments vignetted(out, kBins, gains);
  // Pixels 1 and 2 of the image: 2 pixels x 2 bins x 3 channels.
  std::vector<float> direct(12), bounce1(12), bounce2(12), indirect(12);
  for (int i = 0; i < 12; ++i) {
    direct[i] = 0.1f * static_cast<float>(i + 1);
    bounce1[i] = 0.37f / static_cast<float>(i + 3);
    bounce2[i] = 0.011f * static_cast<float>(i * i + 1);
    indirect[i] = bounce1[i] + bounce2[i];
  }
  vignetted.consume({1,
                     2,
                     {{capture::kDirect, direct.data()},
                      {capture::kIndirect, indirect.data()},
                      {capture::bounceComponent(1), bounce1.data()},
                      {capture::bounceComponent(2), bounce2.data()}}});
  ASSERT_EQ(out.first, 1u);
  ASSERT_EQ(out.count, 2u);
  ASSERT_EQ(out.names.size(), 4u);
  for (int i = 0; i < 12; ++i) {
    const float g = gains[1 + i / 6];
    EXPECT_EQ(out.components[0][i], direct[i] * g);
    EXPECT_EQ(out.components[2][i], bounce1[i] * g);
    EXPECT_EQ(out.components[3][i], bounce2[i] * g);
    EXPECT_EQ(out.components[1][i], out.components[2][i] + out.components[3][i]);
  }
}

// The light on the time axis is counted before the gains, as the renderer
// counts the light off it (AxisReport's shares must not change with the
// lens): direct + indirect, the values that are not finite left out.
TEST(VignettedSegmentsTest, CountsTheLightBeforeTheGains) {
  constexpr int32_t kBins = 2;
  Collect out;
  VignettedSegments vignetted(out, kBins, {0.0f, 0.5f});
  std::vector<float> direct(12, 1.0f), indirect(12, 0.25f);
  direct[7] = std::numeric_limits<float>::quiet_NaN();
  vignetted.consume(
      {0, 2, {{capture::kDirect, direct.data()}, {capture::kIndirect, indirect.data()}}});
  EXPECT_EQ(vignetted.lightBeforeGain(), 11.0 + 3.0);
}

}  // namespace
}  // namespace tofsim::pipeline
