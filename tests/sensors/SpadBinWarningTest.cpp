// Render bins coarser than the SPAD's TDC bins are a warning: the light of a
// render bin is spread evenly over the TDC bins it covers, so the histogram
// shows flat steps the render's width where the instrument would resolve
// the pulse. Finer or equal render bins are what the resampling is for: no
// warning.

#include <gtest/gtest.h>

#include "TestVolumes.h"
#include "tofsim/sensors/Common.h"
#include "tofsim/sensors/RunSensor.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {
namespace {

SensorSpec spadWith(const SpadParams& p) { return SensorSpec{"spad", p}; }

VolumeShape shapeWithBins(double renderBin_s) {
  VolumeShape shape;
  shape.width = 2;
  shape.height = 2;
  shape.channels = 1;
  shape.axis.start_s = 0.0;
  shape.axis.bin_width_s = renderBin_s;
  shape.axis.bins = 100;
  return shape;
}

SpadParams tdcBins(double tdcBin_s) {
  SpadParams p;
  p.bins.bin_width_s = tdcBin_s;
  return p;
}

TEST(SpadBinWarningTest, CoarserRenderBinsWarnFinerOnesDoNot) {
  const std::vector<std::string> coarse =
      sensorWarnings(spadWith(tdcBins(17e-12)), shapeWithBins(34e-12), nullptr);
  ASSERT_EQ(coarse.size(), 1u);
  EXPECT_NE(coarse[0].find("render's bins (34 ps) are coarser than the TDC's (17 ps)"),
            std::string::npos)
      << coarse[0];
  EXPECT_NE(coarse[0].find("flat steps 2 TDC bins wide"), std::string::npos) << coarse[0];
  EXPECT_TRUE(sensorWarnings(spadWith(tdcBins(17e-12)), shapeWithBins(17e-12), nullptr).empty());
  EXPECT_TRUE(sensorWarnings(spadWith(tdcBins(17e-12)), shapeWithBins(5e-12), nullptr).empty());
  // No `bin_width`: the TDC bins are the render's.
  EXPECT_TRUE(sensorWarnings(spadWith(SpadParams{}), shapeWithBins(34e-12), nullptr).empty());
}

// What the warning is about: one render bin of light over 4 TDC bins gives 4
// equal TDC bins (a flat step), whatever the light's shape within the bin.
TEST(SpadBinWarningTest, CoarseRenderBinIsAFlatStep) {
  const TimeAxis render{0.0, 40e-12, 3};
  const TimeAxis tdc{0.0, 10e-12, 12};
  std::vector<double> out;
  resampleEnergy({0.0, 1.0, 0.0}, render, tdc, out);
  for (int i = 4; i < 8; ++i) EXPECT_DOUBLE_EQ(out[i], 0.25) << i;
  EXPECT_EQ(out[3], 0.0);
  EXPECT_EQ(out[8], 0.0);
}

}  // namespace
}  // namespace tofsim::sensors
