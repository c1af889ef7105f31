// Time gating of the SPAD (gate_start, gate_width): a disarmed detector
// detects nothing, so light before the gate (an NLOS capture's first bounce)
// neither counts nor piles up the light inside it, whose histogram follows
// the first-photon law of the gated flux alone.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "TestVolumes.h"
#include "support/ChiSquare.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {
namespace {

using test::array;
using test::makeVolume;

constexpr double kW = 10e-12;  // TDC and render bin width
constexpr int32_t kBins = 120, kSide = 10;

// A blinding peak (bins 10-12, ~3 photons per cycle: almost every cycle
// detects there) and a weak hidden signal (bins 60-89).
std::vector<double> firstBounceAndHidden() {
  std::vector<double> flux(kBins, 0.0);
  for (int t = 10; t < 13; ++t) flux[t] = 1.0;
  for (int t = 60; t < 90; ++t) flux[t] = 0.004 * (1.0 + 0.5 * std::sin(0.3 * t));
  return flux;
}

std::vector<double> counts(const std::vector<double>& flux, const SpadParams& p, uint64_t seed) {
  TransientVolume v = makeVolume(kSide, kSide, 0.0, kW, kBins);
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x)
      for (int t = 0; t < kBins; ++t) v.at(y, x, t, 0) = static_cast<float>(flux[t]);
  const std::vector<SensorOutput> outputs = runSpad(v, p, seed);
  const SensorOutput& c = array(outputs, "spad_counts");
  std::vector<double> sum(kBins, 0.0);
  for (std::size_t i = 0; i < c.data.size(); ++i) sum[i % kBins] += c.data[i];
  return sum;
}

SpadParams gated(double start_s, double width_s) {
  SpadParams p;
  p.cycles = 20000;
  p.pde = 1.0;
  p.gate_start_s = start_s;
  p.gate_width_s = width_s;
  return p;
}

// Pearson's statistic of `h` against the first-photon law of `lawFlux`, with
// the cycles that detected nothing as one more cell.
tofsim::test::ChiSquare againstLaw(std::vector<double> h, const std::vector<double>& lawFlux,
                                   int64_t cycles) {
  std::vector<double> law(lawFlux.size());
  for (std::size_t t = 0; t < law.size(); ++t) law[t] = static_cast<float>(lawFlux[t]);
  std::vector<double> expected = firstPhotonProbabilities(law);
  const double n = double(kSide * kSide) * double(cycles);
  double none = 1.0, detected = 0.0;
  for (std::size_t t = 0; t < expected.size(); ++t) {
    none -= expected[t];
    detected += h[t];
    expected[t] *= n;
  }
  h.push_back(n - detected);
  expected.push_back(n * none);
  // Cells the law gives nothing must have nothing (else the law is
  // impossible: an infinite statistic); Pearson skips them.
  std::vector<double> hk, ek;
  bool impossible = false;
  for (std::size_t t = 0; t < h.size(); ++t) {
    if (expected[t] > 0.0) {
      hk.push_back(h[t]);
      ek.push_back(expected[t]);
    } else {
      impossible = impossible || h[t] != 0.0;
    }
  }
  tofsim::test::ChiSquare chi = tofsim::test::pearson(hk, ek);
  if (impossible) chi.statistic = std::numeric_limits<double>::infinity();
  return chi;
}

TEST(SpadGateTest, LightBeforeTheGateMakesNoCountAndTheRestFollowsTheGatedLaw) {
  const std::vector<double> flux = firstBounceAndHidden();
  // Armed from bin 30.5 to the end: bin 30 is armed for half its width.
  const SpadParams p = gated(30.5 * kW, 200 * kW);
  const std::vector<double> h = counts(flux, p, 11);
  for (int t = 0; t < 30; ++t) EXPECT_EQ(h[t], 0.0) << "bin " << t;
  std::vector<double> law = flux;
  for (int t = 0; t < 30; ++t) law[t] = 0.0;
  law[30] *= 0.5;
  const tofsim::test::ChiSquare chi = againstLaw(h, law, p.cycles);
  EXPECT_LT(chi.statistic, tofsim::test::chiSquareQuantile(chi.dof, 3.09));
  EXPECT_GT(chi.statistic, tofsim::test::chiSquareQuantile(chi.dof, -3.09));
  // The hidden signal's counts are those of a detector that never saw the
  // peak: ungated, the peak takes ~95 % of the cycles first.
  const std::vector<double> blind = counts(flux, gated(0.0, 0.0), 11);
  double hidden = 0.0, blinded = 0.0;
  for (int t = 60; t < 90; ++t) {
    hidden += h[t];
    blinded += blind[t];
  }
  EXPECT_GT(hidden, 10.0 * blinded);
}

// The test above can fail: the counts of a gate opening at bin 62 against
// the law of one opening half a bin later, and against no gate at all.
TEST(SpadGateTest, TheGatedLawTestRejectsAShiftedOrMissingGate) {
  const std::vector<double> flux = firstBounceAndHidden();
  const SpadParams p = gated(62 * kW, 40 * kW);  // bins 62-101
  const std::vector<double> h = counts(flux, p, 12);
  std::vector<double> right = flux;
  for (int t = 0; t < kBins; ++t) {
    if (t < 62 || t >= 102) right[t] = 0.0;
  }
  const tofsim::test::ChiSquare chi = againstLaw(h, right, p.cycles);
  EXPECT_LT(chi.statistic, tofsim::test::chiSquareQuantile(chi.dof, 3.09));
  std::vector<double> halfLate = right;
  halfLate[62] *= 0.5;
  const tofsim::test::ChiSquare shifted = againstLaw(h, halfLate, p.cycles);
  EXPECT_GT(shifted.statistic, tofsim::test::chiSquareQuantile(shifted.dof, 3.09));
  const tofsim::test::ChiSquare ungated = againstLaw(h, flux, p.cycles);
  EXPECT_GT(ungated.statistic, tofsim::test::chiSquareQuantile(ungated.dof, 3.09));
  // and without the gate the peak is counted, which the gated counts are not.
  EXPECT_GT(counts(flux, gated(0.0, 0.0), 12)[11], 1000.0);
  EXPECT_EQ(h[11], 0.0);
}

TEST(SpadGateTest, DarkCountsOnlyInsideTheGate) {
  const std::vector<double> none(kBins, 0.0);
  SpadParams p = gated(20 * kW, 50 * kW);
  p.dark_count_rate_per_s = 2e6;
  const std::vector<double> h = counts(none, p, 13);
  double inside = 0.0;
  for (int t = 0; t < kBins; ++t) {
    if (t < 20 || t >= 70) {
      EXPECT_EQ(h[t], 0.0) << "bin " << t;
    } else {
      inside += h[t];
    }
  }
  // 2e6 /s x 10 ps = 2e-5 per bin and cycle, 50 bins, 100 pixels, 20000 cycles.
  const double expected = 2e-5 * 50 * 100 * 20000;
  EXPECT_NEAR(inside, expected, 5.0 * std::sqrt(expected));
}

}  // namespace
}  // namespace tofsim::sensors
