// The exact event-driven SPAD (SpadEventEngine.h) against the laws the fast
// path draws from: the first-photon law of the synchronous mode
// (firstPhotonProbabilities, chi-square over 10^6 cycles) and the periodic
// steady state of the free-running mode with dead time
// (freeRunningProbabilities), each test with a variant that must fail.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "FirstPhotonChiSquare.h"
#include "SpadEventEngine.h"
#include "TestVolumes.h"
#include "support/ChiSquare.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {
namespace {

// A floor (ambient) and a peak: n q from ~1 to ~10^4 per bin over 10^6 cycles.
std::vector<double> floorAndPeak() {
  std::vector<double> flux(120, 2e-4);
  for (int t = 50; t < 70; ++t) flux[t] += 0.05 * std::exp(-0.04 * (t - 60) * (t - 60));
  return flux;
}

std::vector<double> events(const std::vector<double>& flux, uint64_t cycles, int32_t deadBins,
                           uint64_t seed) {
  Rng rng(seed, 1);
  std::vector<double> h(flux.size(), 0.0);
  detail::DetectorLaws laws;  // deadBins < 0: synchronous first photon
  laws.deadBins = std::max(deadBins, 0);
  laws.stops = deadBins < 0 ? 1 : 0;
  detail::spadEvents(flux, cycles, laws, rng, h);
  return h;
}

// Free-running with Bernoulli(p) afterpulses of one Exp(tau) delay (bins).
detail::DetectorLaws freeRunningAfterpulses(int32_t deadBins, double p, double tau) {
  detail::DetectorLaws laws;
  laws.deadBins = deadBins;
  laws.stops = 0;
  laws.afterpulses.mean = p;
  laws.afterpulses.delays_bins = {tau};
  return laws;
}

TEST(SpadEventEngineTest, SynchronousEventsFollowTheFirstPhotonLaw) {
  const std::vector<double> flux = floorAndPeak();
  const double n = 1e6;
  const std::vector<double> h = events(flux, 1000000, -1, 3);
  const tofsim::test::ChiSquare chi = againstFirstPhoton(h, flux, n);
  EXPECT_LT(chi.statistic, tofsim::test::chiSquareQuantile(chi.dof, 3.09));
  EXPECT_GT(chi.statistic, tofsim::test::chiSquareQuantile(chi.dof, -3.09));
  // The same events against a law 2 % off in flux: rejected.
  std::vector<double> distorted = flux;
  for (double& f : distorted) f *= 1.02;
  const tofsim::test::ChiSquare off = againstFirstPhoton(h, distorted, n);
  EXPECT_GT(off.statistic, tofsim::test::chiSquareQuantile(off.dof, 3.09));
}

// The largest |z| of the per-bin counts against N m_i (m: the law's
// detection probability per cycle), with the binomial standard deviation.
double worstZ(const std::vector<double>& h, const std::vector<double>& m, double cycles) {
  double worst = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double mean = cycles * m[i];
    const double sd = std::sqrt(std::max(cycles * m[i] * (1.0 - m[i]), 1e-12));
    worst = std::max(worst, std::fabs(h[i] - mean) / sd);
  }
  return worst;
}

TEST(SpadEventEngineTest, FreeRunningEventsFollowTheDeadTimeSteadyState) {
  std::vector<double> flux = floorAndPeak();
  for (double& f : flux) f *= 10.0;  // pile-up and dead time matter: ~0.5 per bin at the peak
  const double n = 1e6;
  for (int32_t dead : {0, 5, 40}) {
    SCOPED_TRACE("dead bins " + std::to_string(dead));
    const std::vector<double> h = events(flux, 1000000, dead, 4 + dead);
    EXPECT_LT(worstZ(h, freeRunningProbabilities(flux, dead), n), 5.0);
    // A dead time one bin longer is a different law: some bin shows it.
    EXPECT_GT(worstZ(h, freeRunningProbabilities(flux, dead + 1), n), 8.0);
  }
}

// A constant flux f per bin and d dead bins: q / (1 + d q) detections per
// bin and cycle (the non-paralysable rate law), whatever the cycle length.
TEST(SpadEventEngineTest, ConstantFluxGivesTheNonParalysableRate) {
  const double f = 0.02;
  const double q = -std::expm1(-f);
  const std::vector<double> flux(50, f);
  const double n = 200000;
  for (int32_t dead : {3, 120}) {  // 120 bins: the dead time spans more than two cycles
    const std::vector<double> h = events(flux, 200000, dead, 9);
    double total = 0.0;
    for (double c : h) total += c;
    const double expected = n * 50 * q / (1.0 + dead * q);
    EXPECT_NEAR(total, expected, 5.0 * std::sqrt(expected)) << dead;
  }
}

// Afterpulsing on a constant flux f per bin, d dead bins, an afterpulse with
// probability p and an Exp(tau) delay from the end of the hold-off: the
// detector is live again at bin boundaries, so the intervals between those
// are i.i.d. floor(W) + d + 1 with W ~ Exp(f + 1/tau) (an afterpulse pending,
// probability p) or Exp(f), and E floor(W) = e^-l / (1 - e^-l): the renewal
// rate 1 / (d + 1 + p g(f + 1/tau) + (1 - p) g(f)) detections per bin.
double renewalRate(double f, int32_t d, double p, double tau) {
  const auto g = [](double l) { return std::exp(-l) / -std::expm1(-l); };
  return 1.0 / (d + 1 + p * g(f + 1.0 / tau) + (1.0 - p) * g(f));
}

TEST(SpadEventEngineTest, AfterpulsesFollowTheRenewalRate) {
  const double f = 0.01;
  const std::vector<double> flux(40, f);
  const uint64_t cycles = 100000;
  const double bins = 40.0 * cycles;
  for (const auto& [p, tau] : {std::pair{0.3, 5.0}, std::pair{0.6, 40.0}}) {
    Rng rng(21, 1);
    std::vector<double> h(flux.size(), 0.0);
    detail::spadEvents(flux, cycles, freeRunningAfterpulses(4, p, tau), rng, h);
    double total = 0.0;
    for (double c : h) total += c;
    const double expected = bins * renewalRate(f, 4, p, tau);
    // Renewal counts: variance ~ mean x (interval variance / mean^2) < mean here.
    EXPECT_NEAR(total, expected, 5.0 * std::sqrt(expected)) << p << " " << tau;
    // Fails when mis-parametrised: the same counts against p x 1.2 and against no afterpulsing.
    EXPECT_GT(std::fabs(total - bins * renewalRate(f, 4, 1.2 * p, tau)), 5.0 * std::sqrt(expected));
    EXPECT_GT(std::fabs(total - bins * renewalRate(f, 4, 0.0, tau)), 5.0 * std::sqrt(expected));
  }
}

// After a bright pulse, afterpulses make a tail: each live start with an
// afterpulse pending (probability p after every avalanche, the pulse's and the
// afterpulses' own) detects floor(D) bins later, D ~ Exp(tau), and is live
// again d + 1 bins after that. The expected counts per bin by that recursion
// over live starts; nothing else fires in the tail.
std::vector<double> expectedTail(int32_t firstLive, int32_t bins, int32_t dead, double p,
                                 double tau) {
  std::vector<double> pendingAt(bins + dead + 2, 0.0), counts(bins, 0.0);
  pendingAt[firstLive] = p;
  const double stay = std::exp(-1.0 / tau);
  for (int32_t b = firstLive; b < bins; ++b) {
    double inBin = pendingAt[b] * (1.0 - stay);  // detects in bin b, b + 1, ...
    for (int32_t k = b; k < bins && inBin > 1e-15; ++k, inBin *= stay) {
      counts[k] += inBin;
      pendingAt[k + dead + 1] += inBin * p;
    }
  }
  return counts;
}

// Pearson's statistic of an afterpulse tail, bins [16, 200) in groups of 8,
// against cycles x the per-cycle law: every group is a cell (the law is
// absolute, not fitted to the total), so dof = the number of groups.
tofsim::test::ChiSquare tailChiSquare(const std::vector<double>& h, const std::vector<double>& law,
                                      double cycles) {
  tofsim::test::ChiSquare fit;
  for (int b = 16; b < 200; b += 8) {
    double observed = 0.0, e = 0.0;
    for (int k = b; k < b + 8; ++k) {
      observed += h[k];
      e += cycles * law[k];
    }
    fit.statistic += (observed - e) * (observed - e) / e;
    ++fit.dof;
  }
  return fit;
}

TEST(SpadEventEngineTest, AfterpulsesMakeATailAsTheirRenewalPredicts) {
  std::vector<double> flux(400, 0.0);
  flux[10] = 8.0;  // every cycle detects here (but for e^-8)
  const int32_t dead = 5;
  const double tau = 30.0, p = 0.5;
  const double cycles = 200000;
  Rng rng(22, 1);
  std::vector<double> h(flux.size(), 0.0);
  detail::spadEvents(flux, 200000, freeRunningAfterpulses(dead, p, tau), rng, h);
  const std::vector<double> law = expectedTail(16, 400, dead, p, tau);
  const tofsim::test::ChiSquare fit = tailChiSquare(h, law, cycles);
  EXPECT_LT(fit.statistic, tofsim::test::chiSquareQuantile(fit.dof, 3.09));
  // A delay 10 % longer is rejected.
  const tofsim::test::ChiSquare off =
      tailChiSquare(h, expectedTail(16, 400, dead, p, 1.1 * tau), cycles);
  EXPECT_GT(off.statistic, tofsim::test::chiSquareQuantile(off.dof, 3.09));
  EXPECT_EQ(h[11], 0.0);  // dead after the pulse
}

// The SPAD model with afterpulsing (free-running) draws its pixels with the
// engine: its counts show the tail the recursion predicts, pooled over pixels.
TEST(SpadEventEngineTest, TheSpadModelsAfterpulsesAreTheEngines) {
  const double w = 10e-12;
  TransientVolume v = test::makeVolume(4, 4, 0.0, w, 400);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) v.at(y, x, 10, 0) = 8.0f;
  SpadParams p;
  p.mode = SpadMode::FreeRunning;
  p.cycles = 20000;
  p.pde = 1.0;
  p.dead_time_s = 5 * w;
  p.afterpulse_probability = 0.5;
  p.afterpulse_delays_s = {30 * w};
  const std::vector<SensorOutput> outs = runSpad(v, p, 5);
  const SensorOutput& c = test::array(outs, "spad_counts");
  std::vector<double> h(400, 0.0);
  for (std::size_t i = 0; i < c.data.size(); ++i) h[i % 400] += c.data[i];
  const std::vector<double> law = expectedTail(16, 400, 5, 0.5, 30.0);
  const tofsim::test::ChiSquare fit = tailChiSquare(h, law, 16.0 * 20000);
  EXPECT_LT(fit.statistic, tofsim::test::chiSquareQuantile(fit.dof, 3.09));
  // Without afterpulses the tail is empty.
  p.afterpulse_probability = 0.0;
  const std::vector<SensorOutput> plain = runSpad(v, p, 5);
  double tail = 0.0;
  const SensorOutput& pc = test::array(plain, "spad_counts");
  for (std::size_t i = 0; i < pc.data.size(); ++i) {
    if (i % 400 >= 16) tail += pc.data[i];
  }
  EXPECT_EQ(tail, 0.0);
}

TEST(SpadEventEngineTest, NoFluxNoEventsAndTheSameSeedTheSameCounts) {
  EXPECT_EQ(events(std::vector<double>(10, 0.0), 1000, -1, 1), std::vector<double>(10, 0.0));
  const std::vector<double> flux = floorAndPeak();
  EXPECT_EQ(events(flux, 10000, 5, 7), events(flux, 10000, 5, 7));
  EXPECT_NE(events(flux, 10000, 5, 7), events(flux, 10000, 5, 8));
}

}  // namespace
}  // namespace tofsim::sensors
