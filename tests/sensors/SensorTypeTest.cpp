// The sensor descriptors: every model is described once, an undescribed
// parameter struct fails the compile-time check, and the dispatch reaches
// each model.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "TestVolumes.h"
#include "tofsim/sensors/RunSensor.h"
#include "tofsim/sensors/WindowLoss.h"

namespace tofsim::sensors {
namespace {

struct UndescribedParams {
  SensorCommon common;
};

// What SensorSpec.h asserts for SensorParams: a new alternative without a
// SensorType<> would make the variant fail it, so the build stops.
static_assert(SensorModel<StreakParams> && SensorModel<SpadParams> && SensorModel<CwTofParams>);
static_assert(!SensorModel<UndescribedParams>);
static_assert(!detail::allDescribed(
    static_cast<const std::variant<StreakParams, UndescribedParams>*>(nullptr)));

template <typename P>
void expectRunsAsItsType(const TransientVolume& volume) {
  SensorSpec spec{"s", P{}};
  SensorInputs in;
  in.volume = &volume;
  in.seed = 1;
  const std::vector<SensorOutput> outs = runSensor(spec, in);
  ASSERT_FALSE(outs.empty());
  // Every model prefixes its outputs with its type name, and says what each
  // dimension is: one axis name per dimension, a time axis exactly where one
  // of them is time, and that axis the length of its dimension.
  for (const SensorOutput& o : outs) {
    EXPECT_EQ(o.name.rfind(sensorTypeName(spec.params), 0), 0u) << o.name;
    ASSERT_EQ(o.axes.size(), o.shape.size()) << o.name;
    const auto t = std::find(o.axes.begin(), o.axes.end(), "t");
    ASSERT_EQ(o.time.has_value(), t != o.axes.end()) << o.name;
    if (o.time) {
      EXPECT_EQ(o.shape[t - o.axes.begin()], o.time->bins) << o.name;
    }
    if (o.kind == SensorOutput::Kind::Image || o.kind == SensorOutput::Kind::ColorMappedImage) {
      // Images are (y, x), a streak's (t, x): EXR rows and columns.
      EXPECT_EQ(o.axes.back(), "x") << o.name;
    }
  }
}

TEST(SensorTypeTest, CwTofOutputsSayTheirFrequencyRangeAndSign) {
  const TransientVolume v = test::makeVolume(4, 3, 0.0, 10e-12, 16);
  Image truth(4, 3, 1);
  for (float& d : truth.data) d = 1.0f;
  CwTofParams p;
  p.frequencies_Hz = {20e6, 100e6};
  const std::vector<SensorOutput> outs = runCwTof(v, p, 1, CwTofReferences{&truth, nullptr});
  const auto attribute = [](const SensorOutput& o, const std::string& key) {
    for (const auto& [k, value] : o.attributes) {
      if (k == key) return value;
    }
    return -1.0;
  };
  const double k = v.axis().depthPerSecond_m_per_s();
  const SensorOutput& d100 = test::output(outs, "cwtof_depth_100MHz");
  EXPECT_DOUBLE_EQ(attribute(d100, "frequency_Hz"), 100e6);
  EXPECT_DOUBLE_EQ(attribute(d100, "range_m"), k / 100e6);
  EXPECT_FALSE(d100.signed_values);
  EXPECT_TRUE(test::output(outs, "cwtof_mpi_error").signed_values);
  EXPECT_TRUE(test::output(outs, "cwtof_multipath_error_20MHz").signed_values);
  EXPECT_EQ(test::array(outs, "cwtof_raw").axes,
            (std::vector<std::string>{"frequency", "phase_step", "y", "x"}));
}

TEST(SensorTypeTest, NamesAreUniqueAndDispatchReachesEachModel) {
  std::set<std::string> names;
  const auto addName = [&](const SensorParams& p) { names.insert(sensorTypeName(p)); };
  addName(StreakParams{});
  addName(SpadParams{});
  addName(CwTofParams{});
  addName(ApdParams{});
  EXPECT_EQ(names, (std::set<std::string>{"streak", "spad", "cwtof", "apd"}));
  const TransientVolume v = test::makeVolume(4, 3, 0.0, 10e-12, 16);
  expectRunsAsItsType<StreakParams>(v);
  expectRunsAsItsType<SpadParams>(v);
  expectRunsAsItsType<CwTofParams>(v);
  expectRunsAsItsType<ApdParams>(v);
}

TEST(SensorTypeTest, OutputBytesAndWindowLossComeFromTheModel) {
  const TimeAxis axis{0.0, 10e-12, 100};
  const std::uintmax_t images = 8 * 4 * 3 * (4 + 3);
  StreakParams streak;
  streak.rows = {0, 2};
  EXPECT_EQ(sensorOutputBytes(streak, 4, 3, axis), 2u * 4 * 100 * (4 + 3) + images);
  EXPECT_EQ(sensorOutputBytes(SpadParams{}, 4, 3, axis), 4u * 3 * 100 * 4 + images);
  CwTofParams cw;
  cw.frequencies_Hz = {20e6, 100e6};
  // Raw (F, N) plus phase (F) arrays, then four images with pictures per
  // frequency, and the wiggling sweep (F, S).
  EXPECT_EQ(sensorOutputBytes(cw, 4, 3, axis), 2u * (4 + 1) * 4 * 3 * 4 + 2u * 4 * 4 * 3 * (4 + 3) +
                                                   2u * kWigglingSweepPoints * 4 + images);
  // Light in the render's last bin, a SPAD window that ends before it.
  TransientVolume v = test::makeVolume(1, 1, 0.0, 10e-12, 100);
  v.at(0, 0, 99, 0) = 1.0f;
  SpadParams spad;
  spad.bins.count = 50;
  EXPECT_DOUBLE_EQ(windowLossFraction(spad, v), 1.0);
  EXPECT_DOUBLE_EQ(windowLossFraction(cw, v), 0.0);  // CW-ToF integrates every bin
}

}  // namespace
}  // namespace tofsim::sensors
