// The exact event-driven SPAD (SpadEventEngine.h) against the laws the fast
// path draws from: the first-photon law of the synchronous mode
// (firstPhotonProbabilities, chi-square over 10^6 cycles) and the periodic
// steady state of the free-running mode with dead time
// (freeRunningProbabilities), each test with a variant that must fail.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "SpadEventEngine.h"
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
  detail::spadEvents(flux, cycles, deadBins, rng, h);
  return h;
}

tofsim::test::ChiSquare againstFirstPhoton(std::vector<double> h, const std::vector<double>& law,
                                           double cycles) {
  std::vector<double> expected = firstPhotonProbabilities(law);
  double none = 1.0, detected = 0.0;
  for (std::size_t t = 0; t < expected.size(); ++t) {
    none -= expected[t];
    detected += h[t];
    expected[t] *= cycles;
  }
  h.push_back(cycles - detected);
  expected.push_back(cycles * none);
  return tofsim::test::pearson(h, expected);
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

TEST(SpadEventEngineTest, NoFluxNoEventsAndTheSameSeedTheSameCounts) {
  EXPECT_EQ(events(std::vector<double>(10, 0.0), 1000, -1, 1), std::vector<double>(10, 0.0));
  const std::vector<double> flux = floorAndPeak();
  EXPECT_EQ(events(flux, 10000, 5, 7), events(flux, 10000, 5, 7));
  EXPECT_NE(events(flux, 10000, 5, 7), events(flux, 10000, 5, 8));
}

}  // namespace
}  // namespace tofsim::sensors
