// The instrument window's defaults (the render's axis) and the fraction of
// light an explicit window drops.

#include <gtest/gtest.h>

#include "TestVolumes.h"
#include "tofsim/sensors/Common.h"
#include "tofsim/sensors/WindowLoss.h"

namespace tofsim::sensors {
namespace {

TEST(WindowLossTest, DefaultWindowIsTheRenderAxis) {
  const TimeAxis render{4.5e-9, 10e-12, 300};
  const TimeAxis axis = resolveBins(InstrumentBins{}, render);
  EXPECT_DOUBLE_EQ(axis.start_s, render.start_s);
  EXPECT_DOUBLE_EQ(axis.bin_width_s, render.bin_width_s);
  EXPECT_EQ(axis.bins, render.bins);
  // An explicit offset or count wins; the other part still follows the render.
  InstrumentBins explicitOffset;
  explicitOffset.offset_s = 5e-9;
  EXPECT_DOUBLE_EQ(resolveBins(explicitOffset, render).start_s, 5e-9);
  EXPECT_EQ(resolveBins(explicitOffset, render).bins, 250);  // to the render's end, 7.5 ns
  InstrumentBins explicitCount;
  explicitCount.count = 100;
  EXPECT_DOUBLE_EQ(resolveBins(explicitCount, render).start_s, render.start_s);
  EXPECT_EQ(resolveBins(explicitCount, render).bins, 100);
}

// Bin t of every pixel holds t + 1 (channel 0): a window over the first k
// bins keeps sum_{t<k}(t+1) = k(k+1)/2 of T(T+1)/2.
TEST(WindowLossTest, FractionOutsideAnExplicitWindow) {
  TransientVolume v = test::makeVolume(3, 2, 1e-9, 10e-12, 20);
  for (int32_t y = 0; y < 2; ++y) {
    for (int32_t x = 0; x < 3; ++x) {
      for (int32_t t = 0; t < 20; ++t) v.at(y, x, t, 0) = static_cast<float>(t + 1);
    }
  }
  SpadParams spad;
  EXPECT_DOUBLE_EQ(windowLossFraction(spad, v), 0.0);  // the default window holds it all
  spad.bins.count = 10;
  EXPECT_NEAR(windowLossFraction(spad, v), 1.0 - 55.0 / 210.0, 1e-12);
  // Half a bin's overlap keeps half of it: start at bin 0.5, keep bins 0.5 .. 20.
  spad.bins.count = 0;
  spad.bins.offset_s = 1e-9 + 5e-12;
  EXPECT_NEAR(windowLossFraction(spad, v), 0.5 / 210.0, 1e-12);
  StreakParams streak;
  streak.rows = {1};
  streak.bins.offset_s = 0.0;
  streak.bins.count = 110;  // [0, 1.1 ns): render bins 0 .. 9 of [1, 1.2) ns
  EXPECT_NEAR(windowLossFraction(streak, v), 1.0 - 55.0 / 210.0, 1e-9);
  EXPECT_DOUBLE_EQ(windowLossFraction(CwTofParams{}, v), 0.0);  // no window
}

}  // namespace
}  // namespace tofsim::sensors
