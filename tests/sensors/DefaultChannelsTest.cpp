// A sensor without `channel` or `channel_weights` sees the sum of the volume's
// channels: a blue-only scene is as bright to it as with [1, 1, 1] (it used to
// see the red channel alone, and a blue box gave a sixth of the counts).

#include <gtest/gtest.h>

#include <numeric>

#include "TestVolumes.h"
#include "tofsim/sensors/Common.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {
namespace {

using test::array;
using test::makeVolume;

// Light in the blue channel only: 1e-3 photons per bin over 10 bins.
TransientVolume blueOnly() {
  TransientVolume v = makeVolume(4, 4, 0.0, 10e-12, 20, 3);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int t = 5; t < 15; ++t) v.at(y, x, t, 2) = 1e-3f;
  return v;
}

TEST(DefaultChannelsTest, DefaultSelectionIsTheSumOfTheChannels) {
  TransientVolume v = makeVolume(1, 1, 0.0, 1e-12, 1, 3);
  v.at(0, 0, 0, 0) = 1.0f;
  v.at(0, 0, 0, 1) = 2.0f;
  v.at(0, 0, 0, 2) = 4.0f;
  SensorCommon common;
  EXPECT_NO_THROW(checkChannelSelection(common.channel, v));
  std::vector<double> s;
  pixelSignal(v, common, 0, 0, s);
  EXPECT_DOUBLE_EQ(s[0], 7.0);
}

TEST(DefaultChannelsTest, BlueOnlySceneCountsAsWithWeightsOfOne) {
  const TransientVolume v = blueOnly();
  SpadParams byDefault;
  byDefault.cycles = 10000;
  byDefault.pde = 1.0;
  SpadParams ones = byDefault;
  ones.common.channel.weights = {1.0, 1.0, 1.0};
  const std::vector<SensorOutput> outA = runSpad(v, byDefault, 7);
  const std::vector<SensorOutput> outB = runSpad(v, ones, 7);
  const std::vector<float>& a = array(outA, "spad_counts").data;
  const std::vector<float>& b = array(outB, "spad_counts").data;
  // Same signal, same seed: the same counts, bin for bin.
  EXPECT_EQ(a, b);
  // And not nothing: 16 pixels x 10^4 cycles x ~10^-2 photons per cycle.
  EXPECT_GT(std::accumulate(a.begin(), a.end(), 0.0), 1000.0);
}

}  // namespace
}  // namespace tofsim::sensors
