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
#include "SpadFlimImages.h"
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

// A first-photon histogram at 30 % detections per cycle: pile-up pulls the
// raw counts early (a shorter lifetime); Coates' histogram, N times its
// flux, gives the lifetime back within 1 %.
TEST(FlimFit, PileUpBiasesTheRawHistogramAndCoatesCorrectsIt) {
  const TimeAxis axis = flimAxis();
  const FlimFitter fitter(irf(axis), axis);
  const double tau = 2.5e-9;
  const int64_t cycles = 100000;
  std::vector<double> flux;
  fitter.expected(0.3, 1e-6, tau, 3e-9, flux);  // detections per cycle without losses
  std::vector<double> mu = firstPhotonProbabilities(flux);
  for (double& m : mu) m *= static_cast<double>(cycles);
  double rawMean = 0.0, coatesMean = 0.0;
  const int seeds = 40;
  FlimFitter::Scratch scratch;
  for (int k = 0; k < seeds; ++k) {
    const std::vector<double> h = poisson(mu, 2000 + k);
    std::vector<double> lossless = coatesEstimate(h, cycles);
    for (double& v : lossless) v *= static_cast<double>(cycles);
    const FlimFit raw = fitter.fit(h, scratch), coates = fitter.fit(lossless, scratch);
    ASSERT_TRUE(raw.converged && coates.converged);
    rawMean += raw.lifetime_s / seeds;
    coatesMean += coates.lifetime_s / seeds;
  }
  std::printf("pile-up: raw %.4f ns, Coates %.4f ns (true 2.5)\n", rawMean * 1e9, coatesMean * 1e9);
  EXPECT_LT(rawMean, 0.95 * tau);
  EXPECT_NEAR(coatesMean, tau, 0.01 * tau);
}

// An IRF with a delayed tail (a SPAD's diffusion tail): its phasor is far
// from 1, so the calibration matters.
BinKernel tailedIrf(const TimeAxis& axis) {
  return gaussianTailKernel(fwhmToSigma(300e-12), 0.3, 400e-12, axis.bin_width_s);
}

TEST(FlimPhasor, MonoExponentialsLieOnTheSemicircle) {
  const TimeAxis axis = flimAxis();
  const BinKernel k = tailedIrf(axis);
  const FlimFitter fitter(k, axis);
  const FlimPhasor calibrated(k, axis), uncalibrated(BinKernel{}, axis);
  EXPECT_DOUBLE_EQ(calibrated.frequency_Hz(), 40e6);
  for (const double tau : {0.5e-9, 1.2e-9, 2.5e-9}) {
    const Phasor want = detail::monoExponentialPhasor(tau, 40e6);
    std::vector<double> mu;
    fitter.expected(1e5, 2.0, tau, 1e-9, mu);
    // The expected histogram, the onset and background known: the binning
    // alone is left (second order in w x bin width).
    const Phasor exact = calibrated.of(mu, 2.0, 1e-9);
    EXPECT_NEAR(exact.g, want.g, 1e-3) << tau;
    EXPECT_NEAR(exact.s, want.s, 1e-3) << tau;
    const Phasor raw = uncalibrated.of(mu, 2.0, 1e-9);
    EXPECT_GT(std::hypot(raw.g - want.g, raw.s - want.s), 0.02) << tau;
    // Poisson draws, the onset and background from the fit (as the outputs
    // are made): the mean over seeds within 4 standard errors.
    const int seeds = 40;
    double g = 0, s = 0, g2 = 0, s2 = 0;
    FlimFitter::Scratch scratch;
    for (int seed = 0; seed < seeds; ++seed) {
      const std::vector<double> h = poisson(mu, 3000 + seed);
      const FlimFit fit = fitter.fit(h, scratch);
      ASSERT_TRUE(fit.converged);
      const Phasor p = detail::flimPhasorOf(fitter, calibrated, h, fit, scratch);
      g += p.g, s += p.s, g2 += p.g * p.g, s2 += p.s * p.s;
    }
    g /= seeds, s /= seeds;
    const double seG = std::sqrt((g2 / seeds - g * g) / seeds);
    const double seS = std::sqrt((s2 / seeds - s * s) / seeds);
    std::printf("tau %.1f ns: g %.5f (semicircle %.5f, se %.5f), s %.5f (%.5f, se %.5f)\n",
                tau * 1e9, g, want.g, seG, s, want.s, seS);
    EXPECT_NEAR(g, want.g, 4.0 * seG + 2e-4) << tau;
    EXPECT_NEAR(s, want.s, 4.0 * seS + 2e-4) << tau;
  }
}

TEST(FlimPhasor, BiExponentialLiesOnTheChordAtItsPhotonFractions) {
  const TimeAxis axis = flimAxis();
  const BinKernel k = tailedIrf(axis);
  const FlimFitter fitter(k, axis);
  const FlimPhasor phasor(k, axis);
  const double tau1 = 0.6e-9, tau2 = 3.0e-9, f2 = 0.35;
  std::vector<double> mu, second;
  fitter.expected(1e5 * (1.0 - f2), 1.0, tau1, 3e-9, mu);
  fitter.expected(1e5 * f2, 0.0, tau2, 3e-9, second);
  for (std::size_t i = 0; i < mu.size(); ++i) mu[i] += second[i];
  const Phasor p1 = detail::monoExponentialPhasor(tau1, 40e6);
  const Phasor p2 = detail::monoExponentialPhasor(tau2, 40e6);
  const double dg = p2.g - p1.g, ds = p2.s - p1.s, len2 = dg * dg + ds * ds;
  const auto along = [&](const Phasor& p) { return ((p.g - p1.g) * dg + (p.s - p1.s) * ds) / len2; };
  const auto off = [&](const Phasor& p) {
    return std::fabs((p.g - p1.g) * ds - (p.s - p1.s) * dg) / std::sqrt(len2);
  };
  const Phasor exact = phasor.of(mu, 1.0, 3e-9);
  EXPECT_NEAR(along(exact), f2, 2e-3);
  EXPECT_LT(off(exact), 1e-3);
  EXPECT_LT(std::hypot(exact.g - 0.5, exact.s), 0.5 - 0.05);  // well inside the semicircle
  // A mono-exponential of the mean lifetime is not there.
  std::vector<double> mono;
  fitter.expected(1e5, 1.0, (1.0 - f2) * tau1 + f2 * tau2, 3e-9, mono);
  EXPECT_GT(off(phasor.of(mono, 1.0, 3e-9)), 0.02);
  // Poisson draws, the phasor as the outputs make it (flimPhasorOf).
  const int seeds = 40;
  double t = 0.0, d = 0.0;
  FlimFitter::Scratch scratch;
  for (int seed = 0; seed < seeds; ++seed) {
    const std::vector<double> h = poisson(mu, 4000 + seed);
    const FlimFit fit = fitter.fit(h, scratch);
    ASSERT_TRUE(fit.converged);
    const Phasor p = detail::flimPhasorOf(fitter, phasor, h, fit, scratch);
    t += along(p) / seeds;
    d += off(p) / seeds;
  }
  std::printf("bi-exponential: along the chord %.4f (photon fraction %.2f), off it %.4f\n", t, f2, d);
  EXPECT_NEAR(t, f2, 0.01);
  EXPECT_LT(d, 0.005);
}

// Through the SPAD model: a lit pixel gets its lifetime, a dim and a dark
// one NaN, counted in the metadata; without `flim` no FLIM output at all.
TEST(FlimOutputs, PixelsWithFewCountsAreNaNAndCounted) {
  const TimeAxis axis = flimAxis();
  TransientVolume volume = test::makeVolume(3, 1, axis.start_s, axis.bin_width_s, axis.bins);
  const FlimFitter noIrf(BinKernel{}, axis);
  std::vector<double> decay;
  noIrf.expected(1.0, 0.0, 2e-9, 2e-9, decay);  // photons per cycle, summing to ~1
  for (int32_t i = 0; i < axis.bins; ++i) {
    volume.at(0, 0, i, 0) = static_cast<float>(0.02 * decay[i]);
    volume.at(0, 1, i, 0) = static_cast<float>(2e-6 * decay[i]);
  }
  SpadParams p;
  p.cycles = 200000;
  p.pde = 1.0;
  p.flim = true;
  p.flim_min_counts = 100;
  const std::vector<SensorOutput> outs = runSpad(volume, p, 7);
  const SensorOutput& lifetime = test::output(outs, "spad_lifetime");
  const SensorOutput& sigma = test::output(outs, "spad_lifetime_sigma");
  EXPECT_NEAR(lifetime.data[0], 2e-9, 4.0 * sigma.data[0]);
  EXPECT_LT(sigma.data[0], 0.05e-9);
  for (const char* name : {"spad_lifetime", "spad_lifetime_sigma", "spad_phasor_g", "spad_phasor_s"}) {
    const SensorOutput& o = test::output(outs, name);
    EXPECT_FALSE(std::isnan(o.data[0])) << name;
    EXPECT_TRUE(std::isnan(o.data[1]) && std::isnan(o.data[2])) << name;
  }
  double below = -1.0;
  for (const auto& [key, value] : lifetime.attributes) {
    if (key == "pixels_below_min_counts") below = value;
  }
  EXPECT_EQ(below, 2.0);
  EXPECT_NE(findOutput(outs, "spad_phasor_plot", SensorOutput::Kind::ColorMappedImage), nullptr);
  p.flim = false;
  EXPECT_EQ(findOutput(runSpad(volume, p, 7), "spad_lifetime", SensorOutput::Kind::Image), nullptr);
}

}  // namespace
}  // namespace tofsim::sensors
