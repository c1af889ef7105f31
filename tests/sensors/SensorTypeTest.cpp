// The sensor descriptors: every model is described once, an undescribed
// parameter struct fails the compile-time check, and the dispatch reaches
// each model.

#include <gtest/gtest.h>

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
  // Every model prefixes its outputs with its type name.
  for (const SensorOutput& o : outs) {
    EXPECT_EQ(o.name.rfind(sensorTypeName(spec.params), 0), 0u) << o.name;
  }
}

TEST(SensorTypeTest, NamesAreUniqueAndDispatchReachesEachModel) {
  std::set<std::string> names;
  const auto addName = [&](const SensorParams& p) { names.insert(sensorTypeName(p)); };
  addName(StreakParams{});
  addName(SpadParams{});
  addName(CwTofParams{});
  EXPECT_EQ(names, (std::set<std::string>{"streak", "spad", "cwtof"}));
  const TransientVolume v = test::makeVolume(4, 3, 0.0, 10e-12, 16);
  expectRunsAsItsType<StreakParams>(v);
  expectRunsAsItsType<SpadParams>(v);
  expectRunsAsItsType<CwTofParams>(v);
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
  // Raw (F, N) plus phase (F) arrays, then four images with pictures per frequency.
  EXPECT_EQ(sensorOutputBytes(cw, 4, 3, axis),
            2u * (4 + 1) * 4 * 3 * 4 + 2u * 4 * 4 * 3 * (4 + 3) + images);
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
