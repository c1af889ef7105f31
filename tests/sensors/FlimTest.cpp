// The SPAD's FLIM outputs (sensors/src/FlimFit, FlimPhasor, SpadFlimImages):
// statistical tests on mono- and bi-exponential decays convolved with a
// Gaussian IRF under Poisson noise. The maximum-likelihood lifetime is
// unbiased and its stated uncertainty is its spread over many seeds, and
// fitting without the IRF reconvolution is biased; the pile-up of a
// first-photon histogram biases the raw fit and Coates' histogram corrects
// it; the IRF-calibrated phasor of a mono-exponential lies on the universal
// semicircle (not without the calibration), a bi-exponential's on the chord
// at its photon fractions; pixels with few counts are NaN and counted.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "FlimFit.h"
#include "FlimPhasor.h"
#include "TestVolumes.h"
#include "tofsim/sensors/Random.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/sensors/TimeKernel.h"

namespace tofsim::sensors {
namespace {

using detail::FlimFit;
using detail::FlimFitter;
using detail::FlimPhasor;
using detail::Phasor;

// A TCSPC histogram of a 40 MHz laser: 25 ns in 256 bins (97.7 ps).
TimeAxis flimAxis() {
  TimeAxis axis;
  axis.start_s = 0.0;
  axis.bins = 256;
  axis.bin_width_s = 25e-9 / axis.bins;
  return axis;
}

// A Gaussian IRF of 300 ps FWHM (a SPAD with a picosecond diode laser).
BinKernel irf(const TimeAxis& axis) {
  return gaussianKernel(fwhmToSigma(300e-12), axis.bin_width_s);
}

std::vector<double> poisson(const std::vector<double>& mu, uint64_t seed) {
  Rng rng(seed, 41);
  std::vector<double> h(mu.size());
  for (std::size_t i = 0; i < mu.size(); ++i) h[i] = static_cast<double>(rng.poisson(mu[i]));
  return h;
}

struct Spread {
  double meanTau = 0.0, meanPull = 0.0, pullSd = 0.0;
  int n = 0;
};

// Fits of `fitter` to Poisson draws of `mu` over `seeds` seeds: the mean
// lifetime and the pulls (tau^ - tau) / sigma^.
Spread fitSpread(const FlimFitter& fitter, const std::vector<double>& mu, double tau_s, int seeds) {
  Spread r;
  FlimFitter::Scratch scratch;
  double sumPull2 = 0.0;
  for (int k = 0; k < seeds; ++k) {
    const FlimFit fit = fitter.fit(poisson(mu, 1000 + k), scratch);
    EXPECT_TRUE(fit.converged);
    if (!fit.converged) continue;
    const double pull = (fit.lifetime_s - tau_s) / fit.lifetime_sigma_s;
    r.meanTau += fit.lifetime_s;
    r.meanPull += pull;
    sumPull2 += pull * pull;
    ++r.n;
  }
  r.meanTau /= r.n;
  r.meanPull /= r.n;
  r.pullSd = std::sqrt(sumPull2 / r.n - r.meanPull * r.meanPull);
  return r;
}

TEST(FlimFit, RecoversTheLifetimeWithinItsUncertaintyOverManySeeds) {
  const TimeAxis axis = flimAxis();
  const FlimFitter fitter(irf(axis), axis);
  const double tau = 2.5e-9;
  std::vector<double> mu;
  // 20000 photons of the decay, 2 counts per bin of background.
  fitter.expected(2e4, 2.0, tau, 3e-9, mu);
  const int seeds = 200;
  const Spread r = fitSpread(fitter, mu, tau, seeds);
  ASSERT_EQ(r.n, seeds);
  std::printf("tau %.5f ns (true 2.5), mean pull %.3f, pull sd %.3f\n", r.meanTau * 1e9, r.meanPull,
              r.pullSd);
  EXPECT_NEAR(r.meanTau, tau, 0.01 * tau);
  // Unbiased to a sixth of its own sigma, and the stated sigma is the spread.
  EXPECT_LT(std::fabs(r.meanPull), 4.0 / std::sqrt(seeds));
  EXPECT_NEAR(r.pullSd, 1.0, 0.15);
}

TEST(FlimFit, WithoutTheIrfReconvolutionIsBiased) {
  const TimeAxis axis = flimAxis();
  const FlimFitter withIrf(irf(axis), axis), without(BinKernel{}, axis);
  const double tau = 0.8e-9;
  std::vector<double> mu;
  withIrf.expected(2e4, 2.0, tau, 3e-9, mu);
  const int seeds = 100;
  const Spread good = fitSpread(withIrf, mu, tau, seeds);
  const Spread bad = fitSpread(without, mu, tau, seeds);
  std::printf("with IRF %.5f ns (pull %.2f), without %.5f ns (pull %.2f), true 0.8\n",
              good.meanTau * 1e9, good.meanPull, bad.meanTau * 1e9, bad.meanPull);
  EXPECT_LT(std::fabs(good.meanPull), 4.0 / std::sqrt(seeds));
  EXPECT_GT(std::fabs(bad.meanPull), 3.0);  // off by 3 of its sigmas, on average
}

}  // namespace
}  // namespace tofsim::sensors
