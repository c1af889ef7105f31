// Comparison metrics on tiny hand-made volumes with answers worked out by hand.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tofsim/compare/VolumeComparison.h"
#include "tofsim/util/Error.h"

namespace tofsim::compare {
namespace {

const TimeAxis kAxis{1e-9, 1e-10, 4};  // bins start at 1.0, 1.1, 1.2, 1.3 ns

TransientVolume volume(int32_t w = 2, int32_t h = 1, int32_t channels = 1) {
  std::vector<std::string> names;
  for (int32_t c = 0; c < channels; ++c) names.push_back("C" + std::to_string(c));
  return TransientVolume(w, h, kAxis, names);
}

TEST(VolumeComparisonTest, IdenticalVolumesHaveZeroError) {
  TransientVolume a = volume();
  a.at(0, 0, 1, 0) = 2.0f;
  a.at(0, 1, 3, 0) = 1.0f;
  const VolumeComparison r = compareVolumes(a, a);
  EXPECT_EQ(r.steadyRelativeL1, 0.0);
  EXPECT_EQ(r.steadyRmse, 0.0);
  EXPECT_EQ(r.transientRelativeL1, 0.0);
  EXPECT_EQ(r.maxEarliestArrivalDifference_s, 0.0);
  EXPECT_EQ(r.arrivalPixelsCompared, 2u);
}

TEST(VolumeComparisonTest, HandComputedMetrics) {
  // B (reference): pixel 0 = [0, 4, 0, 0], pixel 1 = [0, 0, 2, 2].
  // A (test):      pixel 0 = [0, 0, 4, 0], pixel 1 = [0, 1, 1, 3].
  TransientVolume a = volume(), b = volume();
  b.at(0, 0, 1, 0) = 4;
  b.at(0, 1, 2, 0) = 2;
  b.at(0, 1, 3, 0) = 2;
  a.at(0, 0, 2, 0) = 4;
  a.at(0, 1, 1, 0) = 1;
  a.at(0, 1, 2, 0) = 1;
  a.at(0, 1, 3, 0) = 3;
  const VolumeComparison r = compareVolumes(a, b);
  // Steady: A = (4, 5), B = (4, 4): L1 = 1 / 8, RMSE = sqrt((0 + 1) / 2).
  EXPECT_DOUBLE_EQ(r.steadyRelativeL1, 1.0 / 8.0);
  EXPECT_DOUBLE_EQ(r.steadyRmse, std::sqrt(0.5));
  // Transient: |A - B| = 4 + 4 + 1 + 1 + 1 = 11 over sum |B| = 8.
  EXPECT_DOUBLE_EQ(r.transientRelativeL1, 11.0 / 8.0);
  // Arrival (threshold 5% of peak): pixel 0: A bin 2, B bin 1 -> +0.1 ns;
  // pixel 1: A bin 1 (1 >= 0.15), B bin 2 -> -0.1 ns.
  EXPECT_NEAR(r.earliestArrivalDifference_s.at(0, 0, 0), 1e-10, 1e-16);
  EXPECT_NEAR(r.earliestArrivalDifference_s.at(0, 1, 0), -1e-10, 1e-16);
  EXPECT_NEAR(r.meanEarliestArrivalDifference_s, 1e-10, 1e-16);
  EXPECT_NEAR(r.maxEarliestArrivalDifference_s, 1e-10, 1e-16);
  // Energy per bin.
  EXPECT_EQ(r.energyA, (std::vector<double>{0, 1, 5, 3}));
  EXPECT_EQ(r.energyB, (std::vector<double>{0, 4, 2, 2}));
}

TEST(VolumeComparisonTest, ArrivalThresholdIsAFractionOfThePeakOverChannels) {
  TransientVolume v = volume(1, 1, 2);
  v.at(0, 0, 0, 0) = 0.5f;  // e = 0.5: below 20% of the peak 4
  v.at(0, 0, 1, 1) = 1.0f;  // e = 1.0: 25% of the peak
  v.at(0, 0, 2, 0) = 2.0f;
  v.at(0, 0, 2, 1) = 2.0f;  // peak e = 4
  EXPECT_EQ(earliestArrivalBin(v, 0, 0, 0.2), 1);
  EXPECT_EQ(earliestArrivalBin(v, 0, 0, 0.1), 0);
  EXPECT_EQ(earliestArrivalBin(volume(1, 1), 0, 0, 0.1), -1);
}

TEST(VolumeComparisonTest, PixelsDarkInOneVolumeAreCountedNotCompared) {
  TransientVolume a = volume(), b = volume();
  a.at(0, 0, 0, 0) = 1;
  b.at(0, 0, 0, 0) = 1;
  b.at(0, 1, 0, 0) = 1;
  const VolumeComparison r = compareVolumes(a, b);
  EXPECT_EQ(r.arrivalPixelsCompared, 1u);
  EXPECT_EQ(r.arrivalPixelsUnmatched, 1u);
}

TEST(VolumeComparisonTest, ZeroReferenceGivesZeroOrInfinity) {
  TransientVolume a = volume(), b = volume();
  EXPECT_EQ(compareVolumes(a, b).transientRelativeL1, 0.0);
  a.at(0, 0, 0, 0) = 1;
  EXPECT_EQ(compareVolumes(a, b).steadyRelativeL1, std::numeric_limits<double>::infinity());
}

TEST(VolumeComparisonTest, MismatchedShapesOrAxesAreInputErrors) {
  EXPECT_THROW(compareVolumes(volume(2, 1), volume(1, 2)), InputError);
  EXPECT_THROW(compareVolumes(volume(2, 1, 1), volume(2, 1, 3)), InputError);
  TransientVolume shifted(2, 1, TimeAxis{2e-9, 1e-10, 4}, {"C0"});
  EXPECT_THROW(compareVolumes(volume(), shifted), InputError);
}

TEST(VolumeComparisonTest, EnergyCurveCsvHasOneLinePerBin) {
  // Bin centres 0.25, 0.75, ... s are exact in binary, so the text is too.
  const TimeAxis exact{0.0, 0.5, 4};
  TransientVolume a(2, 1, exact, {"C0"}), b(2, 1, exact, {"C0"});
  a.at(0, 0, 1, 0) = 0.5f;
  b.at(0, 1, 3, 0) = 2.0f;
  const std::string csv = energyCurveCsv(compareVolumes(a, b));
  EXPECT_EQ(csv,
            "bin,time_s,energy_a,energy_b\n"
            "0,0.25,0,0\n"
            "1,0.75,0.5,0\n"
            "2,1.25,0,0\n"
            "3,1.75,0,2\n");
  EXPECT_NE(summaryTable(compareVolumes(a, b)).find("transient relative L1"), std::string::npos);
}

}  // namespace
}  // namespace tofsim::compare
