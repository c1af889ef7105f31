// Afterpulse delays from a measured table (issue 24, item 2's "or a measured
// table"; `afterpulse_delay_table`): the event engine's draws by the table's
// exact inverse against the renewal closed form of the interval law with the
// table's own survival (dense samples of the exponential mixture: the
// mixture's law; two peaks: their law, a shifted table rejected), and the
// fast path's first-order flux with a table against its definition and the
// engine.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "AfterpulseIntervals.h"
#include "SpadAfterpulseFlux.h"
#include "SpadDetector.h"
#include "TestVolumes.h"
#include "support/ChiSquare.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {
namespace {

// Rows (t_k, density(t_k)) at t_k = (k + 1/2) step for t_k < span: each
// row's bin [k step, (k + 1) step) (the midpoint rule of Spad.h).
SpadAfterpulseTable sampled(const std::function<double(double)>& density, double step,
                            double span) {
  std::vector<double> t, v;
  for (double x = 0.5 * step; x < span; x += step) {
    t.push_back(x);
    v.push_back(density(x));
  }
  return afterpulseTable("", t, v);
}

// The survival of a table's piecewise-constant density, summed directly
// (not through the engine's distribution).
double tableSurvival(const SpadAfterpulseTable& t, double y) {
  double above = 0.0;
  for (std::size_t k = 0; k < t.density_per_s.size(); ++k) {
    const double lo = std::max(y, t.edges_s[k]), hi = t.edges_s[k + 1];
    if (hi > lo) above += t.density_per_s[k] * (hi - lo);
  }
  return std::min(1.0, above);
}

detail::DetectorLaws tableLaws(bool poisson, double mean, const SpadAfterpulseTable& table) {
  detail::DetectorLaws laws;
  laws.deadBins = 3;
  laws.stops = 0;
  laws.afterpulses.count =
      poisson ? detail::AfterpulseLaw::Count::Poisson : detail::AfterpulseLaw::Count::Bernoulli;
  laws.afterpulses.mean = mean;
  detail::setAfterpulseTable(laws.afterpulses, table, 1.0);  // a table in bins
  return laws;
}

// The mixture of SpadAfterpulseTest (means 2 and 20 bins, weights 0.7, 0.3)
// sampled every 0.01 bin to 400 bins (e^-20 of the slow trap left out): the
// engine with the table gives the mixture's closed-form interval law; the
// table's piecewise-constant steps change a cell's probability by ~(0.01 /
// 2)^2 / 24, far below the noise. One exponential of the mean delay and no
// afterpulses are rejected.
TEST(SpadAfterpulseTableTest, ATableOfTheMixtureGivesTheMixturesRenewalLaw) {
  const auto mixture = [](double t) {
    return 0.7 / 2.0 * std::exp(-t / 2.0) + 0.3 / 20.0 * std::exp(-t / 20.0);
  };
  const SpadAfterpulseTable table = sampled(mixture, 0.01, 400.0);
  const double r = 0.05;
  for (const bool poisson : {false, true}) {
    SCOPED_TRACE(poisson ? "poisson" : "bernoulli");
    const double mean = poisson ? 0.8 : 0.6;
    const std::vector<double> y = liveTimes(r, tableLaws(poisson, mean, table), 200000, 41);
    const IntervalLaw law{r, poisson, mean, [](double t) {
                            return 0.7 * std::exp(-t / 2.0) + 0.3 * std::exp(-t / 20.0);
                          }};
    const tofsim::test::ChiSquare fit = intervalChiSquare(y, law);
    std::printf("mixture table, %s: chi2 %.1f / %d dof (%zu intervals)\n",
                poisson ? "poisson" : "bernoulli", fit.statistic, fit.dof, y.size());
    EXPECT_LT(fit.statistic, tofsim::test::chiSquareQuantile(fit.dof, 3.09));
    IntervalLaw one = law;
    one.delaySurvival = [](double t) { return std::exp(-t / (0.7 * 2.0 + 0.3 * 20.0)); };
    IntervalLaw none = law;
    none.mean = 0.0;
    for (const IntervalLaw& wrong : {one, none}) {
      const tofsim::test::ChiSquare off = intervalChiSquare(y, wrong);
      EXPECT_GT(off.statistic, tofsim::test::chiSquareQuantile(off.dof, 3.09));
    }
  }
}

// Two peaks, boxes [1, 3) and [10, 14) bins with masses 0.6 and 0.4 (rows
// every 0.5 bin, counts per row in any scale): the interval law with the
// table's survival, which no exponential mixture has; the table shifted by
// half a bin is rejected.
TEST(SpadAfterpulseTableTest, TwoPeaksGiveTheirRenewalLawAndAShiftedTableIsRejected) {
  const auto peaks = [](double t) {
    if (t >= 1.0 && t < 3.0) return 3.0 * 0.6 / 2.0;
    if (t >= 10.0 && t < 14.0) return 3.0 * 0.4 / 4.0;
    return 0.0;
  };
  const SpadAfterpulseTable table = sampled(peaks, 0.5, 20.0);
  EXPECT_NEAR(tableSurvival(table, 3.0), 0.4, 1e-12);  // normalised
  const SpadAfterpulseTable shifted = sampled([&](double t) { return peaks(t - 0.5); }, 0.5, 20.0);
  const double r = 0.05;
  for (const bool poisson : {false, true}) {
    SCOPED_TRACE(poisson ? "poisson" : "bernoulli");
    const double mean = poisson ? 0.8 : 0.6;
    const std::vector<double> y = liveTimes(r, tableLaws(poisson, mean, table), 200000, 43);
    const IntervalLaw law{r, poisson, mean, [&](double t) { return tableSurvival(table, t); }};
    const tofsim::test::ChiSquare fit = intervalChiSquare(y, law);
    IntervalLaw moved = law;
    moved.delaySurvival = [&](double t) { return tableSurvival(shifted, t); };
    const tofsim::test::ChiSquare off = intervalChiSquare(y, moved);
    std::printf("two peaks, %s: chi2 %.1f / %d dof; shifted table %.1f\n",
                poisson ? "poisson" : "bernoulli", fit.statistic, fit.dof, off.statistic);
    EXPECT_LT(fit.statistic, tofsim::test::chiSquareQuantile(fit.dof, 3.09));
    EXPECT_GT(off.statistic, tofsim::test::chiSquareQuantile(off.dof, 3.09));
    // The engine drawing the shifted table is told apart from the table's law.
    const std::vector<double> ys = liveTimes(r, tableLaws(poisson, mean, shifted), 200000, 44);
    EXPECT_GT(intervalChiSquare(ys, law).statistic, tofsim::test::chiSquareQuantile(fit.dof, 3.09));
  }
}

// P(s <= delay < s + 1) of a table in bins, integrated from its rows.
std::vector<double> wholeBinMasses(const SpadAfterpulseTable& t, int64_t bins) {
  std::vector<double> m(bins, 0.0);
  for (int64_t s = 0; s < bins; ++s) m[s] = tableSurvival(t, s) - tableSurvival(t, s + 1.0);
  return m;
}

// The fixed point with a table against its definition summed directly: m =
// freeRunningProbabilities(flux'), flux'_i = flux_i + mean sum_j m_j sum_s
// P(s <= delay < s + 1) [j + deadBins + 1 + s = i on the cycle]; tables
// within the cycle and 2.5 cycles long, dead times 0, 5 and 130 bins.
TEST(SpadAfterpulseTableTest, FastFixedPointWithATableIsTheFirstOrderFlux) {
  constexpr int32_t B = 100;
  std::vector<double> flux(B, 0.002);
  for (int i = 17; i < 24; ++i) flux[i] += 0.8 * std::exp(-0.3 * (i - 20) * (i - 20));
  const SpadAfterpulseTable near = sampled(
      [](double t) { return t < 5.0 ? 1.0 : (t > 20.0 && t < 30.0 ? 0.5 : 0.0); }, 0.3, 31.0);
  const SpadAfterpulseTable wide = sampled([](double t) { return 1.0 + 0.01 * t; }, 0.7, 250.0);
  for (const SpadAfterpulseTable* table : {&near, &wide})
    for (const int32_t dead : {0, 5, 130}) {
      SCOPED_TRACE("dead bins " + std::to_string(dead) + ", table to " +
                   std::to_string(table->edges_s.back()));
      detail::AfterpulseLaw law;
      law.count = detail::AfterpulseLaw::Count::Poisson;
      law.mean = 0.1;
      law.reset = false;
      detail::setAfterpulseTable(law, *table, 1.0);
      detail::FirstOrderAfterpulses out;
      detail::firstOrderAfterpulses(flux, dead, law, out);
      const std::vector<double> m = freeRunningProbabilities(out.flux, dead);
      const std::vector<double> masses = wholeBinMasses(*table, 260);
      std::vector<double> image = flux;
      for (int32_t j = 0; j < B; ++j)
        for (std::size_t s = 0; s < masses.size(); ++s)
          image[(j + dead + 1 + s) % B] += law.mean * masses[s] * m[j];
      for (int32_t i = 0; i < B; ++i) {
        EXPECT_NEAR(out.detections[i], m[i], 1e-12) << i;
        EXPECT_NEAR(out.flux[i], image[i], 1e-11) << i;
      }
      // The table's releases are in it; the other table's are not.
      const SpadAfterpulseTable& other = table == &near ? wide : near;
      detail::AfterpulseLaw otherLaw = law;
      detail::setAfterpulseTable(otherLaw, other, 1.0);
      detail::FirstOrderAfterpulses o;
      detail::firstOrderAfterpulses(flux, dead, otherLaw, o);
      double worst = 0.0;
      for (int32_t i = 0; i < B; ++i) worst = std::max(worst, std::fabs(o.flux[i] - image[i]));
      EXPECT_GT(worst, 1e-4);
    }
}

// Through the SPAD model, free-running, 64 pixels of a floor and a bright
// return at bin 20 (SpadFastAfterpulseTest's scene), a two-peak table (in
// seconds): the afterpulse excess in bins 30.. of `engine: exact` against
// `engine: fast`'s expected (its law, noise free) and the fast path's counts
// against that law; without afterpulses the engine's tail is told apart.
constexpr int32_t kBins = 100;
constexpr double kWidth = 10e-12;

TransientVolume scene() {
  TransientVolume v = test::makeVolume(8, 8, 0.0, kWidth, kBins);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      for (int t = 0; t < kBins; ++t) v.at(y, x, t, 0) = 0.002f;
      for (int t = 17; t < 24; ++t)
        v.at(y, x, t, 0) += 0.8f * std::exp(-0.3f * (t - 20) * (t - 20));
    }
  return v;
}

double tail(const TransientVolume& v, const SpadParams& p, uint64_t seed) {
  const std::vector<SensorOutput> outs = runSpad(v, p, seed);
  const SensorOutput& c = test::array(outs, "spad_counts");
  double t = 0.0;
  for (std::size_t i = 0; i < c.data.size(); ++i)
    if (i % kBins >= 30) t += c.data[i];
  return t;
}

TEST(SpadAfterpulseTableTest, FastPathWithATableTracksTheEngine) {
  const TransientVolume v = scene();
  // Peaks at 4-8 and 25-45 bins after the live moment (rows every bin).
  std::vector<double> t, counts;
  for (int k = 0; k < 60; ++k) {
    t.push_back((k + 0.5) * kWidth);
    counts.push_back(k >= 4 && k < 8 ? 50.0 : (k >= 25 && k < 45 ? 10.0 : 0.0));
  }
  const SpadAfterpulseTable table = afterpulseTable("", t, counts);
  const double mu = 0.1;
  const int64_t cycles = 100000;
  SpadParams p;
  p.mode = SpadMode::FreeRunning;
  p.cycles = cycles;
  p.pde = 1.0;
  p.dead_time_s = 5 * kWidth;
  p.afterpulse_probability = mu;
  p.afterpulse_count = SpadAfterpulseCount::Poisson;
  p.afterpulse_traps = SpadAfterpulseTraps::Keep;
  p.afterpulse_delay_table = table;
  // The fast path's law: the first-order fixed point of one pixel's flux.
  std::vector<double> flux(kBins);
  for (int i = 0; i < kBins; ++i) flux[i] = v.at(0, 0, i, 0);
  const auto expectedTail = [&](double mean) {
    detail::AfterpulseLaw law;
    law.count = detail::AfterpulseLaw::Count::Poisson;
    law.mean = mean;
    law.reset = false;
    detail::setAfterpulseTable(law, table, kWidth);
    detail::FirstOrderAfterpulses out;
    detail::firstOrderAfterpulses(flux, 5, law, out);
    double s = 0.0;
    for (int i = 30; i < kBins; ++i) s += out.detections[i];
    return s * 64.0 * static_cast<double>(cycles);
  };
  const double expectedFast = expectedTail(mu), expectedNone = expectedTail(0.0);
  p.engine = SpadEngine::Exact;
  const double exact = tail(v, p, 1);
  p.engine = SpadEngine::Fast;
  const double fast = tail(v, p, 2);
  const double zFast = (fast - expectedFast) / std::sqrt(expectedFast);
  const double excess = exact - expectedNone;
  const double ratio = (expectedFast - expectedNone) / excess;
  std::printf(
      "table, mu %g: afterpulse excess fast (expected) / exact %.0f / %.0f = %.4f (engine's sd "
      "%.4f); fast tail z %.2f\n",
      mu, expectedFast - expectedNone, excess, ratio, std::sqrt(exact) / excess, zFast);
  EXPECT_LT(std::fabs(zFast), 5.0);
  EXPECT_NEAR(ratio, 1.0, 0.02);
  // Without afterpulses the engine's tail is far from the table's.
  EXPECT_GT(excess, 10.0 * std::sqrt(exact));
}

}  // namespace
}  // namespace tofsim::sensors
