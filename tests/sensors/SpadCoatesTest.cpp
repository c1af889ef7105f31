// Coates' correction in its multi-stop, dead-time form (coatesEstimate with
// stops and deadBins): histograms of the event engine with unlimited stops
// behind a dead time, inside the cycle and past its end, give back the true
// flux per bin (chi-square over the bins), where the one-stop correction
// fails; with one stop and a dead time inside the cycle it is the classic
// correction, bit for bit.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "SpadEventEngine.h"
#include "support/ChiSquare.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {
namespace {

std::vector<double> engine(const std::vector<double>& flux, uint64_t cycles, int32_t deadBins,
                           int64_t stops, uint64_t seed) {
  detail::DetectorLaws laws;
  laws.deadBins = deadBins;
  laws.stops = stops;
  Rng rng(seed, 1);
  std::vector<double> h(flux.size(), 0.0);
  detail::spadEvents(flux, cycles, laws, rng, h);
  return h;
}

// 24 bins: a bright return over a floor, q up to ~0.6 per bin.
std::vector<double> returnFlux() {
  std::vector<double> flux(24, 0.03);
  for (int t = 6; t < 18; ++t) flux[t] += 0.9 * std::exp(-0.1 * (t - 12) * (t - 12));
  return flux;
}

// Sum over bins of (estimate - flux)^2 / var, var = q / ((1 - q) L) the
// estimate's variance from h ~ Binomial(L, q) (delta method), L the live
// cycles the estimate used: ~ chi-square(bins) when it is unbiased.
double chiSquareOfEstimate(const std::vector<double>& estimate, const std::vector<double>& flux,
                           const std::vector<double>& h) {
  double chi = 0.0;
  for (std::size_t i = 0; i < flux.size(); ++i) {
    const double q = -std::expm1(-flux[i]);
    const double live = h[i] / -std::expm1(-estimate[i]);  // L with h / L = q-hat
    const double var = q / ((1.0 - q) * live);
    chi += (estimate[i] - flux[i]) * (estimate[i] - flux[i]) / var;
  }
  return chi;
}

TEST(SpadCoatesTest, UnlimitedStopsBehindADeadTimeGiveTheTrueFlux) {
  const std::vector<double> flux = returnFlux();
  const int dof = static_cast<int>(flux.size());
  constexpr uint64_t kCycles = 400000;
  for (const int32_t d : {3, 30}) {  // 30: past the 24-bin cycle into the next
    SCOPED_TRACE(d);
    const std::vector<double> h = engine(flux, kCycles, d, 0, 17 + d);
    const double chi = chiSquareOfEstimate(coatesEstimate(h, kCycles, 0, d), flux, h);
    std::printf("unlimited stops, dead time %d bins: chi-square %.1f on %d bins\n", d, chi, dof);
    EXPECT_LT(chi, test::chiSquareQuantile(dof, 3.09));
    // Without the dead time, or as Coates' one-stop correction, it is far off.
    EXPECT_GT(chiSquareOfEstimate(coatesEstimate(h, kCycles, 0, 0), flux, h),
              test::chiSquareQuantile(dof, 3.09));
    EXPECT_GT(chiSquareOfEstimate(coatesEstimate(h, kCycles), flux, h),
              test::chiSquareQuantile(dof, 3.09));
    // A dead time one bin off is seen too.
    EXPECT_GT(chiSquareOfEstimate(coatesEstimate(h, kCycles, 0, d + 1), flux, h),
              test::chiSquareQuantile(dof, 3.09));
  }
}

TEST(SpadCoatesTest, OneStopInsideTheCycleIsTheClassicCorrection) {
  const std::vector<double> flux = returnFlux();
  std::vector<double> h = engine(flux, 100000, 2, 1, 5);
  h[22] = h[23] = 0.0;  // no count whose 2-bin dead time reaches the next cycle
  ASSERT_FALSE(deadTimeReachesNextCycle(h, 2));
  EXPECT_EQ(coatesEstimate(h, 100000, 1, 2), coatesEstimate(h, 100000));
  EXPECT_TRUE(deadTimeReachesNextCycle(engine(std::vector<double>(24, 0.03), 1000, 2, 1, 5), 2));
}

}  // namespace
}  // namespace tofsim::sensors
