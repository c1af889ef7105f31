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
#include "support/ShortNumber.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {
namespace {

using test::array;
using test::makeVolume;
using test::output;
using tofsim::test::sci;

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

// A step gate at bin b on a constant flux phi per bin: nothing before b,
// and after it the geometric law q (1 - q)^(i - b), q = 1 - exp(-phi),
// written here in closed form (not through firstPhotonProbabilities).
TEST(SpadGateTest, StepGateOnAConstantFluxGivesTheGeometricLawFromItsBin) {
  constexpr int b = 40;
  constexpr double phi = 0.05;
  SpadParams p = gated(b * kW, 200 * kW);
  p.dark_count_rate_per_s = phi / kW;  // phi per bin, every bin
  const std::vector<double> h = counts(std::vector<double>(kBins, 0.0), p, 21);
  const double n = double(kSide * kSide) * double(p.cycles), q = -std::expm1(-phi);
  std::vector<double> observed, expected;
  double detected = 0.0, none = 1.0;
  for (int i = 0; i < kBins; ++i) {
    detected += h[i];
    if (i < b) {
      EXPECT_EQ(h[i], 0.0) << "bin " << i;
      continue;
    }
    const double law = q * std::pow(1.0 - q, i - b);
    none -= law;
    observed.push_back(h[i]);
    expected.push_back(n * law);
  }
  observed.push_back(n - detected);
  expected.push_back(n * none);
  const tofsim::test::ChiSquare chi = tofsim::test::pearson(observed, expected);
  RecordProperty("chi2", sci(chi.statistic));
  RecordProperty("dof", chi.dof);
  EXPECT_LT(chi.statistic, tofsim::test::chiSquareQuantile(chi.dof, 3.09));
  EXPECT_GT(chi.statistic, tofsim::test::chiSquareQuantile(chi.dof, -3.09));
  // The same law one bin late is rejected.
  std::vector<double> late = expected;
  for (std::size_t k = 1; k + 1 < late.size(); ++k) late[k] = expected[k - 1];
  late[0] = 0.0;
  std::vector<double> lateObserved(observed.begin() + 1, observed.end() - 1);
  std::vector<double> lateExpected(late.begin() + 1, late.end() - 1);
  EXPECT_GT(tofsim::test::pearson(lateObserved, lateExpected).statistic,
            tofsim::test::chiSquareQuantile(static_cast<int>(lateObserved.size()) - 1, 3.09));
}

// g(t) of a gate with linear ramps, written out independently of the model:
// 0, a line up to 1 over `rise` centred on `start`, 1, a line down over `fall`
// centred on `end`, 0.
double rampGate(double t, double start, double end, double rise, double fall) {
  const double up = rise > 0.0 ? (t - (start - 0.5 * rise)) / rise : (t >= start ? 1.0 : 0.0);
  const double down = fall > 0.0 ? ((end + 0.5 * fall) - t) / fall : (t < end ? 1.0 : 0.0);
  return std::clamp(std::min(up, down), 0.0, 1.0);
}

// The bin average of rampGate by the midpoint rule on 10^5 intervals per
// bin (error below 5e-6 at a hard edge, far less on the ramps).
std::vector<double> numericBinAverages(double start, double end, double rise, double fall) {
  std::vector<double> g(kBins);
  constexpr int m = 100000;
  for (int i = 0; i < kBins; ++i) {
    double sum = 0.0;
    for (int k = 0; k < m; ++k) sum += rampGate((i + (k + 0.5) / m) * kW, start, end, rise, fall);
    g[i] = sum / m;
  }
  return g;
}

SpadParams ramped() {
  SpadParams p = gated(30.3 * kW, 40.0 * kW);  // 50 % points at bins 30.3 and 70.3
  p.gate_rise_s = 7.4 * kW;
  p.gate_fall_s = 3.1 * kW;
  return p;
}

std::vector<double> constantFluxPerCycle(const SpadParams& p, double phi, int32_t y = 0,
                                         int32_t x = 0) {
  SpadParams q = p;
  q.dark_count_rate_per_s = phi / kW;
  const TransientVolume v = makeVolume(kSide, kSide, 0.0, kW, kBins);
  std::vector<double> flux;
  spadFluxPerCycle(v, q, resolveBins(q.bins, v.axis()), y, x, flux);
  return flux;
}

TEST(SpadGateTest, RampBinAveragesAreTheIntegralOfTheRamp) {
  const SpadParams p = ramped();
  const double start = p.gate_start_s, end = start + p.gate_width_s;
  const std::vector<double> flux = constantFluxPerCycle(p, 0.01);
  const std::vector<double> g = numericBinAverages(start, end, p.gate_rise_s, p.gate_fall_s);
  double worst = 0.0;
  for (int i = 0; i < kBins; ++i) worst = std::max(worst, std::fabs(flux[i] / 0.01 - g[i]));
  RecordProperty("max_abs_error", sci(worst));
  EXPECT_LT(worst, 1e-5);
  // The ramps are seen: bins 26-33 and 68-71 are partly armed, 34-67 fully.
  EXPECT_GT(flux[26], 0.0);
  EXPECT_LT(flux[33], 0.01);
  EXPECT_NEAR(flux[50], 0.01, 1e-15);
  EXPECT_EQ(flux[25], 0.0);
  EXPECT_EQ(flux[72], 0.0);
  // Hard edges (rise = fall = 0) are the covered fraction of each bin.
  SpadParams hard = p;
  hard.gate_rise_s = hard.gate_fall_s = 0.0;
  const std::vector<double> step = constantFluxPerCycle(hard, 0.01);
  const std::vector<double> gStep = numericBinAverages(start, end, 0.0, 0.0);
  for (int i = 0; i < kBins; ++i) EXPECT_NEAR(step[i] / 0.01, gStep[i], 1e-5) << "bin " << i;
}

TEST(SpadGateTest, RampedGateFollowsItsLawAndTheHardGateLawIsRejected) {
  const SpadParams p = ramped();
  const double phi = 0.02;
  SpadParams lit = p;
  lit.dark_count_rate_per_s = phi / kW;
  const std::vector<double> h = counts(std::vector<double>(kBins, 0.0), lit, 22);
  const std::vector<double> law = constantFluxPerCycle(p, phi);
  std::vector<double> g = numericBinAverages(p.gate_start_s, p.gate_start_s + p.gate_width_s,
                                             p.gate_rise_s, p.gate_fall_s);
  for (double& v : g) v *= phi;
  const tofsim::test::ChiSquare chi = againstLaw(h, g, p.cycles);
  RecordProperty("chi2", sci(chi.statistic));
  EXPECT_LT(chi.statistic, tofsim::test::chiSquareQuantile(chi.dof, 3.09));
  SpadParams hard = p;
  hard.gate_rise_s = hard.gate_fall_s = 0.0;
  const tofsim::test::ChiSquare wrong = againstLaw(h, constantFluxPerCycle(hard, phi), p.cycles);
  RecordProperty("chi2_hard_law", sci(wrong.statistic));
  EXPECT_GT(wrong.statistic, tofsim::test::chiSquareQuantile(wrong.dof, 3.09));
  EXPECT_EQ(law.size(), g.size());
}

TEST(SpadGateTest, GateSkewIsAFixedPatternOfItsSigma) {
  constexpr int32_t side = 64;
  SpadParams p = gated(30 * kW, 40 * kW);
  p.cycles = 100;
  p.fpn_seed = 5;
  p.gate_skew_sigma_s = 2e-12;
  p.dark_count_rate_per_s = 1e9;  // 0.01 per bin: the gate's edge bins count
  TransientVolume v = makeVolume(side, side, 0.0, kW, kBins);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) v.at(y, x, 35, 0) = 0.5f;
  const auto a = runSpad(v, p, 1), b = runSpad(v, p, 2);
  const std::vector<float>& map = output(a, "spad_gate_skew_map").data;
  EXPECT_EQ(map, output(b, "spad_gate_skew_map").data);
  EXPECT_NE(array(a, "spad_counts").data, array(b, "spad_counts").data);
  SpadParams other = p;
  other.fpn_seed = 6;
  EXPECT_NE(map, output(runSpad(v, other, 1), "spad_gate_skew_map").data);
  // Mean 0 and standard deviation sigma within 4 of their standard errors;
  // a sigma 10 % off is outside.
  const double n = static_cast<double>(map.size()), sigma = p.gate_skew_sigma_s;
  double sum = 0.0, squares = 0.0;
  for (float s : map) sum += s;
  const double mean = sum / n;
  for (float s : map) squares += (s - mean) * (s - mean);
  const double sd = std::sqrt(squares / (n - 1.0));
  RecordProperty("skew_mean_s", sci(mean));
  RecordProperty("skew_sd_s", sci(sd));
  EXPECT_LT(std::fabs(mean), 4.0 * sigma / std::sqrt(n));
  EXPECT_LT(std::fabs(sd - sigma), 4.0 * sigma / std::sqrt(2.0 * n));
  EXPECT_GT(std::fabs(sd - 1.1 * sigma), 4.0 * sigma / std::sqrt(2.0 * n));
  // Each pixel's flux is the unskewed model's with the gate moved by its skew
  // (to the map's float precision).
  for (const auto& [y, x] : {std::pair{0, 0}, std::pair{17, 40}, std::pair{63, 63}}) {
    const double skew = map[static_cast<std::size_t>(y) * side + x];
    SpadParams moved = p;
    moved.gate_skew_sigma_s = 0.0;
    moved.gate_start_s += skew;
    std::vector<double> f, g;
    spadFluxPerCycle(v, p, resolveBins(p.bins, v.axis()), y, x, f);
    spadFluxPerCycle(v, moved, resolveBins(p.bins, v.axis()), y, x, g);
    for (int i = 0; i < kBins; ++i) EXPECT_NEAR(f[i], g[i], 1e-9) << "bin " << i;
    // and not the unskewed gate's: the dark counts of the edge bins move.
    SpadParams unskewed = moved;
    unskewed.gate_start_s = p.gate_start_s;
    std::vector<double> u;
    spadFluxPerCycle(v, unskewed, resolveBins(p.bins, v.axis()), y, x, u);
    EXPECT_GT(std::fabs(f[29] + 2.0 * f[30] - u[29] - 2.0 * u[30]),
              1e-3 * u[30] * std::fabs(skew) / kW);
  }
  SpadParams none = p;
  none.gate_skew_sigma_s = 0.0;
  EXPECT_EQ(findOutput(runSpad(v, none, 1), "spad_gate_skew_map", SensorOutput::Kind::Image),
            nullptr);
}

}  // namespace
}  // namespace tofsim::sensors
