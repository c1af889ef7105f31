// Afterpulsing on the fast path (`engine: fast`, SpadAfterpulseFlux.h), first
// order in the afterpulse mean, against the exact event engine (`engine:
// exact`): the afterpulse excess, the fast path's expected (its law, noise
// free) against the engine's measured at mu = 0.01 and 0.1; the fixed point
// against its definition.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "SpadAfterpulseFlux.h"
#include "TestVolumes.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {
namespace {

constexpr int32_t kBins = 100;
constexpr double kWidth = 10e-12;

// 64 pixels of a floor and a bright return at bin 20.
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

std::vector<double> pooled(const TransientVolume& v, const SpadParams& p, uint64_t seed) {
  const std::vector<SensorOutput> outs = runSpad(v, p, seed);
  const SensorOutput& c = test::array(outs, "spad_counts");
  std::vector<double> h(kBins, 0.0);
  for (std::size_t i = 0; i < c.data.size(); ++i) h[i % kBins] += c.data[i];
  return h;
}

// Two histograms of equal exposure: sum (a - b)^2 / (a + b) over bins with counts.
double twoSample(const std::vector<double>& a, const std::vector<double>& b, int& dof) {
  double chi = 0.0;
  dof = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] + b[i] <= 0.0) continue;
    chi += (a[i] - b[i]) * (a[i] - b[i]) / (a[i] + b[i]);
    ++dof;
  }
  return chi;
}

double tail(const std::vector<double>& h) {
  double t = 0.0;
  for (int i = 30; i < kBins; ++i) t += h[i];
  return t;
}

SpadParams afterpulsing(SpadMode mode, double mu, SpadEngine engine, int64_t cycles = 20000) {
  SpadParams p;
  p.mode = mode;
  p.cycles = cycles;
  p.pde = 1.0;
  p.dead_time_s = mode == SpadMode::FreeRunning ? 5 * kWidth : 0.0;
  p.afterpulse_probability = mu;
  p.afterpulse_count = SpadAfterpulseCount::Poisson;
  p.afterpulse_traps = SpadAfterpulseTraps::Keep;
  p.afterpulse_delays_s = {3 * kWidth, 25 * kWidth};
  p.afterpulse_weights = {0.5, 0.5};
  p.engine = engine;
  return p;
}

// The fast path's law, noise-free: the expected counts in the tail bins 30..
// of the 64 pixels, N sum_i m_i, m of the scene's flux (pde 1, no blur: the
// volume's values) through the first-order fixed point (afterpulsing()'s law
// in bins; mu = 0: the exact steady state).
double expectedTail(const TransientVolume& v, double mu, int64_t cycles) {
  std::vector<double> flux(kBins);
  for (int t = 0; t < kBins; ++t) flux[t] = v.at(0, 0, t, 0);
  detail::AfterpulseLaw law;
  law.count = detail::AfterpulseLaw::Count::Poisson;
  law.mean = mu;
  law.delays_bins = {3.0, 25.0};
  law.weights = {0.5, 0.5};
  law.reset = false;
  detail::FirstOrderAfterpulses out;
  detail::firstOrderAfterpulses(flux, 5, law, out);
  double t = 0.0;
  for (int i = 30; i < kBins; ++i) t += out.detections[i];
  return t * 64.0 * static_cast<double>(cycles);
}

// The afterpulse excess in bins 30.. (the counts above the no-afterpulse
// law's): the engine's measured, the fast path's expected. Its noise is the
// engine's tail counts' (~1.8 10^5 of background per 2 10^4 cycles): the
// issue's "+15 % at mu = 0.01" (three independent runs of 2 10^4 cycles, the
// excess a difference of two noisy tails) was that noise, sd ~12 % of an
// excess of ~7500. Measured over 16 seeds of 2 10^4 cycles, the fast path's
// expected excess / the engine's: 0.999 +- 0.011 (mu = 0.01) and 0.9953 +-
// 0.0012 (mu = 0.1: second order, what first order leaves out).
// Here (seeds 1, 2, 3): 1.0227 at mu = 0.01 (2 10^5 cycles, the engine's
// Poisson sd 0.019) and 0.9983 at mu = 0.1 (10^5 cycles, sd 0.0027); the
// fast path's tail z -0.19 and 0.09. The test bounds the ratio to 1 +- 0.06
// and 1 +- 0.015 (~3.5 and ~5 sd; an afterpulse mean 10 % off on the fast
// path gives 1.127 and 1.113), checks that the fast path draws its law (its
// tail within 5 sd of the expectation) and that the engine is told apart
// from no afterpulses.
TEST(SpadFastAfterpulseTest, FreeRunningFirstOrderAfterpulsesTrackTheEngine) {
  const TransientVolume v = scene();
  struct Case {
    double mu;
    int64_t cycles;
    double tolerance;
  };
  for (const Case& c : {Case{0.01, 200000, 0.06}, Case{0.1, 100000, 0.015}}) {
    SCOPED_TRACE("mu " + std::to_string(c.mu));
    const auto exact =
        pooled(v, afterpulsing(SpadMode::FreeRunning, c.mu, SpadEngine::Exact, c.cycles), 1);
    const auto fast =
        pooled(v, afterpulsing(SpadMode::FreeRunning, c.mu, SpadEngine::Fast, c.cycles), 2);
    const auto none =
        pooled(v, afterpulsing(SpadMode::FreeRunning, 0.0, SpadEngine::Fast, c.cycles), 3);
    const double expectedNone = expectedTail(v, 0.0, c.cycles);
    const double expectedFast = expectedTail(v, c.mu, c.cycles);
    const double zFast = (tail(fast) - expectedFast) / std::sqrt(expectedFast);
    EXPECT_LT(std::fabs(zFast), 5.0);
    const double excess = tail(exact) - expectedNone;
    const double ratio = (expectedFast - expectedNone) / excess;
    EXPECT_NEAR(ratio, 1.0, c.tolerance);
    std::printf(
        "mu %g, %lld cycles: afterpulse excess fast (expected) / exact %.0f / %.0f = %.4f "
        "(engine's sd %.4f); fast path's tail z %.2f\n",
        c.mu, static_cast<long long>(c.cycles), expectedFast - expectedNone, excess, ratio,
        std::sqrt(tail(exact)) / excess, zFast);
    // Without its extra flux the fast path is told apart from the engine.
    int dof = 0;
    const double off = twoSample(none, exact, dof);
    EXPECT_GT(off, dof + 8.0 * std::sqrt(2.0 * dof));
  }
}

// The fixed point of flux' and its steady state, run a cycle at a time
// (firstOrderAfterpulses), against the definition summed directly: m =
// freeRunningProbabilities(flux') and flux'_i = flux_i + mean sum_c w_c
// sum_j m_j sum_(s >= 0) (1 - lambda_c) lambda_c^s [j + deadBins + 1 + s = i
// on the cycle], the releases' geometric series summed term by term (200
// cycles: lambda^(200 B) is below 1e-100). Also with a dead time longer
// than the cycle.
TEST(SpadFastAfterpulseTest, FixedPointIsTheFirstOrderFluxAndItsSteadyState) {
  for (const int32_t dead : {0, 5, 130}) {
    SCOPED_TRACE("dead bins " + std::to_string(dead));
    constexpr int32_t B = 100;
    std::vector<double> flux(B, 0.002);
    for (int i = 17; i < 24; ++i) flux[i] += 0.8 * std::exp(-0.3 * (i - 20) * (i - 20));
    detail::AfterpulseLaw law;
    law.count = detail::AfterpulseLaw::Count::Poisson;
    law.mean = 0.1;
    law.delays_bins = {3.0, 25.0};
    law.weights = {1.0, 3.0};  // not normalised
    law.reset = false;
    detail::FirstOrderAfterpulses out;
    detail::firstOrderAfterpulses(flux, dead, law, out);
    const std::vector<double> m = freeRunningProbabilities(out.flux, dead);
    std::vector<double> image = flux;
    for (std::size_t c = 0; c < 2; ++c) {
      const double lambda = std::exp(-1.0 / law.delays_bins[c]);
      const double scale = law.mean * law.weights[c] / 4.0 * (1.0 - lambda);
      for (int32_t j = 0; j < B; ++j) {
        double power = 1.0;
        for (int64_t s = 0; s < 200 * B; ++s, power *= lambda)
          image[(j + dead + 1 + s) % B] += scale * power * m[j];
      }
    }
    for (int32_t i = 0; i < B; ++i) {
      EXPECT_NEAR(out.detections[i], m[i], 1e-12) << i;
      EXPECT_NEAR(out.flux[i], image[i], 1e-11) << i;
    }
    // It is a fixed point with afterpulses: flux' is not the flux.
    EXPECT_GT(out.flux[60] - flux[60], 1e-3);
    // Without afterpulses: the flux and its steady state.
    law.mean = 0.0;
    detail::firstOrderAfterpulses(flux, dead, law, out);
    const std::vector<double> steady = freeRunningProbabilities(flux, dead);
    EXPECT_EQ(out.flux, flux);
    for (int32_t i = 0; i < B; ++i) EXPECT_NEAR(out.detections[i], steady[i], 1e-12) << i;
  }
}

// Synchronous afterpulses stay exact under `engine: fast` (the engine draws
// them): the same bytes as `auto`.
TEST(SpadFastAfterpulseTest, SynchronousAfterpulsesStayExact) {
  const TransientVolume v = scene();
  EXPECT_EQ(pooled(v, afterpulsing(SpadMode::Synchronous, 0.1, SpadEngine::Fast), 4),
            pooled(v, afterpulsing(SpadMode::Synchronous, 0.1, SpadEngine::Auto), 4));
}

}  // namespace
}  // namespace tofsim::sensors
