// The time axis: half-open bins, the sides off the axis, metres of path.

#include <gtest/gtest.h>

#include <cmath>

#include "tofsim/volume/PhysicalConstants.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim {
namespace {

TimeAxis axis() {
  TimeAxis a;
  // Binary fractions, so every edge below is exact.
  a.start_s = 0.5;
  a.bin_width_s = 0.25;
  a.bins = 10;
  return a;
}

TEST(TimeAxisTest, BinsAreHalfOpen) {
  const TimeAxis a = axis();
  EXPECT_EQ(a.binOf(a.binStart_s(0)), 0);
  EXPECT_EQ(a.binOf(a.binCenter_s(3)), 3);
  EXPECT_EQ(a.binOf(a.binCenter_s(9)), 9);
  EXPECT_EQ(a.end_s(), 3.0);
  EXPECT_EQ(a.binOf(std::nextafter(a.end_s(), 0.0)), 9);
}

TEST(TimeAxisTest, OffTheAxisBySide) {
  const TimeAxis a = axis();
  EXPECT_EQ(a.binOf(std::nextafter(a.start_s, 0.0)), kBeforeAxis);
  EXPECT_EQ(a.binOf(a.end_s()), kAfterAxis);  // the end belongs to no bin
  EXPECT_EQ(a.binOf(100.0), kAfterAxis);
  EXPECT_EQ(a.binOf(std::nan("")), kBeforeAxis);
  AxisLoss loss;
  loss.add(kBeforeAxis, 1.0);
  loss.add(kAfterAxis, 2.0);
  EXPECT_EQ(loss.before, 1.0);
  EXPECT_EQ(loss.after, 2.0);
  EXPECT_EQ(loss.total(), 3.0);
}

TEST(TimeAxisTest, MetresAreSpeedOfLightTimesSeconds) {
  const TimeAxis a = axis();
  EXPECT_DOUBLE_EQ(a.start_m(), kSpeedOfLight_m_per_s * 0.5);
  EXPECT_DOUBLE_EQ(a.bin_width_m(), kSpeedOfLight_m_per_s * 0.25);
}

}  // namespace
}  // namespace tofsim
