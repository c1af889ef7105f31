// Afterpulsing in the event engine (issue 24, item 2): Bernoulli(p) or
// Poisson(mu) releases per avalanche with delays from a mixture of
// exponentials, against the closed-form interval law of the renewal model
// (dark counts only, traps reset by each avalanche) and, where no closed form
// exists (synchronous mode: releases spill into later cycles and become
// their stops; traps kept), against a bin-by-bin simulation
// (SpadBruteForce.h). Each test with a variant that must fail.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "AfterpulseIntervals.h"
#include "SpadBruteForce.h"
#include "SpadDetector.h"
#include "SpadEventEngine.h"
#include "TestVolumes.h"
#include "support/ChiSquare.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {
namespace {

detail::DetectorLaws mixtureLaws(bool poisson, double mean, bool reset = true) {
  detail::DetectorLaws laws;
  laws.deadBins = 3;
  laws.stops = 0;
  laws.afterpulses.count =
      poisson ? detail::AfterpulseLaw::Count::Poisson : detail::AfterpulseLaw::Count::Bernoulli;
  laws.afterpulses.mean = mean;
  laws.afterpulses.delays_bins = {2.0, 20.0};
  laws.afterpulses.weights = {0.7, 0.3};
  laws.afterpulses.reset = reset;
  return laws;
}

TEST(SpadAfterpulseTest, MixtureDelaysGiveTheRenewalIntervalLaw) {
  const double r = 0.05;
  for (const bool poisson : {false, true}) {
    SCOPED_TRACE(poisson ? "poisson" : "bernoulli");
    const double mean = poisson ? 0.8 : 0.6;
    const std::vector<double> y = liveTimes(r, mixtureLaws(poisson, mean), 200000, 41);
    const IntervalLaw law{r, poisson, mean, mixtureSurvival({2.0, 20.0}, {0.7, 0.3})};
    const tofsim::test::ChiSquare fit = intervalChiSquare(y, law);
    EXPECT_LT(fit.statistic, tofsim::test::chiSquareQuantile(fit.dof, 3.09));
    // Rejected: one exponential of the mixture's mean delay; no afterpulses;
    // the other count law with the same chance of at least one release.
    IntervalLaw one = law;
    one.delaySurvival = mixtureSurvival({0.7 * 2.0 + 0.3 * 20.0}, {1.0});
    IntervalLaw none = law;
    none.mean = 0.0;
    IntervalLaw other = law;
    other.poisson = !poisson;
    other.mean = poisson ? -std::expm1(-mean) : -std::log1p(-mean);
    for (const IntervalLaw& wrong : {one, none, other}) {
      const tofsim::test::ChiSquare off = intervalChiSquare(y, wrong);
      EXPECT_GT(off.statistic, tofsim::test::chiSquareQuantile(off.dof, 3.09));
    }
  }
}

// The largest per-bin |z| of two sets of replicas (per-bin mean counts,
// Welch's standard error from the replicas' spread, so correlations across
// cycles cost nothing).
double worstTwoSampleZ(const std::vector<std::vector<double>>& a,
                       const std::vector<std::vector<double>>& b) {
  const auto stats = [](const std::vector<std::vector<double>>& runs, std::size_t i) {
    double m = 0.0, v = 0.0;
    for (const auto& h : runs) m += h[i] / runs.size();
    for (const auto& h : runs) v += (h[i] - m) * (h[i] - m) / (runs.size() - 1);
    return std::pair{m, v / runs.size()};
  };
  double worst = 0.0;
  for (std::size_t i = 0; i < a[0].size(); ++i) {
    const auto [ma, va] = stats(a, i);
    const auto [mb, vb] = stats(b, i);
    if (va + vb > 0.0) worst = std::max(worst, std::fabs(ma - mb) / std::sqrt(va + vb));
  }
  return worst;
}

detail::DetectorLaws lawsOf(const test::BruteForceSpad& s) {
  detail::DetectorLaws laws;
  laws.deadBins = s.dead;
  laws.stops = s.stops;
  laws.afterpulses.count =
      s.poisson ? detail::AfterpulseLaw::Count::Poisson : detail::AfterpulseLaw::Count::Bernoulli;
  laws.afterpulses.mean = s.mean;
  laws.afterpulses.delays_bins = s.taus;
  laws.afterpulses.weights = s.weights;
  laws.afterpulses.reset = s.reset;
  return laws;
}

constexpr int kReplicas = 40;
constexpr uint64_t kCycles = 5000;

std::vector<std::vector<double>> engineRuns(const test::BruteForceSpad& s) {
  std::vector<std::vector<double>> runs;
  for (int k = 0; k < kReplicas; ++k) {
    Rng rng(51, k);
    std::vector<double> h(s.flux.size(), 0.0);
    detail::spadEvents(s.flux, kCycles, lawsOf(s), rng, h);
    runs.push_back(h);
  }
  return runs;
}

std::vector<std::vector<double>> bruteForceRuns(const test::BruteForceSpad& s) {
  std::vector<std::vector<double>> runs;
  for (int k = 0; k < kReplicas; ++k) {
    Rng rng(52, k);
    runs.push_back(s.run(kCycles, rng));
  }
  return runs;
}

// A bright return in bin 2 of 10 and a floor; the releases of its avalanche
// come after the cycle's end often, so they are the next cycle's stops.
test::BruteForceSpad tinyCase() {
  test::BruteForceSpad s;
  s.flux.assign(10, 0.01);
  s.flux[2] = 1.5;
  return s;
}

TEST(SpadAfterpulseTest, SynchronousAfterpulsesSpillIntoLaterCyclesAsTheBruteForceDoes) {
  struct Case {
    std::string name;
    int32_t dead;
    int64_t stops;
    bool poisson;
    double mean;
    std::vector<double> taus, weights;
    bool reset;
  };
  const std::vector<Case> cases = {
      {"one stop, Bernoulli, reset", 2, 1, false, 0.5, {4.0}, {1.0}, true},
      {"two stops, Poisson mixture, kept", 1, 2, true, 0.6, {1.5, 12.0}, {0.5, 0.5}, false},
      {"dead past the cycle, Poisson, reset", 13, 1, true, 0.4, {6.0}, {1.0}, true},
      {"free-running, Poisson mixture, kept", 3, 0, true, 0.5, {2.0, 9.0}, {0.3, 0.7}, false},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    test::BruteForceSpad s = tinyCase();
    s.dead = c.dead;
    s.stops = c.stops;
    s.poisson = c.poisson;
    s.mean = c.mean;
    s.taus = c.taus;
    s.weights = c.weights;
    s.reset = c.reset;
    const auto oracle = bruteForceRuns(s);
    EXPECT_LT(worstTwoSampleZ(engineRuns(s), oracle), 5.0);
    // The engine without afterpulses is told apart, and with kept traps (where
    // a second release outlives the first's dead time often) the reset rule.
    test::BruteForceSpad off = s;
    off.mean = 0.0;
    EXPECT_GT(worstTwoSampleZ(engineRuns(off), oracle), 10.0);
    if (c.name.find("kept") != std::string::npos) {
      test::BruteForceSpad reset = s;
      reset.reset = true;
      EXPECT_GT(worstTwoSampleZ(engineRuns(reset), oracle), 5.0);
    }
  }
}

// Through the SPAD model (seconds, weights in any scale, synchronous mode):
// its 40 pixels are 40 replicas of the engine, against the brute force.
TEST(SpadAfterpulseTest, TheSpadModelsSynchronousAfterpulsesAreTheBruteForces) {
  const double w = 10e-12;
  test::BruteForceSpad s = tinyCase();
  s.dead = 1;
  s.stops = 1;
  s.poisson = true;
  s.mean = 0.6;
  s.taus = {1.5, 12.0};
  s.weights = {1.0, 3.0};
  s.reset = false;
  TransientVolume v = test::makeVolume(8, 5, 0.0, w, 10);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 8; ++x)
      for (int t = 0; t < 10; ++t) v.at(y, x, t, 0) = static_cast<float>(s.flux[t]);
  SpadParams p;
  p.cycles = kCycles;
  p.pde = 1.0;
  p.dead_time_s = s.dead * w;
  p.afterpulse_probability = s.mean;
  p.afterpulse_count = SpadAfterpulseCount::Poisson;
  p.afterpulse_delays_s = {1.5 * w, 12.0 * w};
  p.afterpulse_weights = {2.0, 6.0};
  p.afterpulse_traps = SpadAfterpulseTraps::Keep;
  const std::vector<SensorOutput> outs = runSpad(v, p, 9);
  const SensorOutput& c = test::array(outs, "spad_counts");
  std::vector<std::vector<double>> pixels;
  for (std::size_t px = 0; px < 40; ++px)
    pixels.emplace_back(&c.data[px * 10], &c.data[px * 10 + 10]);
  const auto oracle = bruteForceRuns(s);
  EXPECT_LT(worstTwoSampleZ(pixels, oracle), 5.0);
  // Weights swapped: rejected.
  test::BruteForceSpad swapped = s;
  swapped.weights = {3.0, 1.0};
  EXPECT_GT(worstTwoSampleZ(pixels, bruteForceRuns(swapped)), 5.0);
}

}  // namespace
}  // namespace tofsim::sensors
