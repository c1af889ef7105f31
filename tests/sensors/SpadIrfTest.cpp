// A measured instrument response (SpadParams::irf) in place of pulse and
// jitter: constant over its own samples and moved into the TDC bins
// exactly. Checked against the Gaussian jitter model, a box response's
// closed-form trapezoid and the three time-zero modes.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "TestVolumes.h"
#include "support/ShortNumber.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/sensors/TimeKernel.h"

namespace tofsim::sensors {
namespace {

using tofsim::test::sci;

using test::makeVolume;

std::vector<double> flux(const TransientVolume& v, const SpadParams& p) {
  std::vector<double> f;
  spadFluxPerCycle(v, p, resolveBins(p.bins, v.axis()), 0, 0, f);
  return f;
}

double maxAbsDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::fabs(a[i] - b[i]));
  return d;
}

// A Gaussian of `sigma` as an IRF: each sample its exact integral over
// [t - h/2, t + h/2), samples at t = k h for |t| <= 8 sigma, zero delay at 0.
SpadIrf gaussianIrf(double sigma, double h) {
  SpadIrf irf;
  const int half = static_cast<int>(std::lround(8.0 * sigma / h));
  const auto cdf = [&](double t) { return 0.5 * std::erfc(-t / (sigma * std::sqrt(2.0))); };
  for (int k = -half; k <= half; ++k) irf.values.push_back(cdf((k + 0.5) * h) - cdf((k - 0.5) * h));
  irf.first_time_s = -half * h;
  irf.sample_width_s = h;
  irf.t0 = SpadIrf::TimeZero::Time;
  irf.t0_s = 0.0;
  return irf;
}

TEST(SpadIrfTest, GaussianIrfReproducesTheJitterModel) {
  // 4 ps bins, a sharp return and a weaker one, ambient: first-photon law
  // of the flux with jitter_fwhm = 1 ps sigma, and with the IRF.
  const double w = 4e-12, sigma = 1e-12;
  TransientVolume v = makeVolume(1, 1, 0.0, w, 64);
  v.at(0, 0, 20, 0) = 0.8f;
  v.at(0, 0, 21, 0) = 0.3f;
  v.at(0, 0, 40, 0) = 0.05f;
  SpadParams jitter;
  jitter.pde = 1.0;
  jitter.ambient_rate_per_s = 1e9;
  jitter.jitter_fwhm_s = sigma * 2.0 * std::sqrt(2.0 * std::log(2.0));
  SpadParams measured = jitter;
  measured.jitter_fwhm_s = 0.0;
  measured.irf = gaussianIrf(sigma, 0.002e-12);
  const std::vector<double> pj = firstPhotonProbabilities(flux(v, jitter));
  const std::vector<double> pm = firstPhotonProbabilities(flux(v, measured));
  const double d = maxAbsDifference(pj, pm);
  RecordProperty("max_abs_difference", sci(d));
  EXPECT_LT(d, 1e-6);
  // Counts: the same seed draws the same histogram.
  EXPECT_EQ(test::array(runSpad(v, jitter, 5), "spad_counts").data,
            test::array(runSpad(v, measured, 5), "spad_counts").data);
  // A response 10 % wider, or none, is far off.
  measured.irf = gaussianIrf(1.1 * sigma, 0.002e-12);
  EXPECT_GT(maxAbsDifference(pj, firstPhotonProbabilities(flux(v, measured))), 1e-3);
  measured.irf = SpadIrf{};
  EXPECT_GT(maxAbsDifference(pj, firstPhotonProbabilities(flux(v, measured))), 1e-3);
}

// A source uniform over its bin [0, w) plus a shift uniform on [0, W): the
// sum has a trapezoid density; its CDF in closed form.
double trapezoidCdf(double s, double w, double W) {
  if (s <= 0.0) return 0.0;
  if (s < w) return s * s / (2.0 * w * W);
  if (s < W) return (s - 0.5 * w) / W;
  if (s < W + w) return 1.0 - (W + w - s) * (W + w - s) / (2.0 * w * W);
  return 1.0;
}

TEST(SpadIrfTest, BoxIrfGivesTheClosedFormTrapezoid) {
  const double w = 10e-12, W = 25e-12;
  const int i0 = 30;
  TransientVolume v = makeVolume(1, 1, 0.0, w, 80);
  v.at(0, 0, i0, 0) = 0.25f;
  SpadParams p;
  p.pde = 1.0;
  // 25 samples of 1 ps, centres 0.5 .. 24.5 ps: the box [0, 25 ps).
  p.irf.values.assign(25, 3.0);
  p.irf.first_time_s = 0.5e-12;
  p.irf.sample_width_s = 1e-12;
  p.irf.t0 = SpadIrf::TimeZero::Time;
  p.irf.t0_s = 0.0;
  std::vector<double> expected(80, 0.0);
  for (int d = 0; d < 5; ++d) {
    expected[i0 + d] = 0.25 * (trapezoidCdf((d + 1) * w, w, W) - trapezoidCdf(d * w, w, W));
  }
  const double err = maxAbsDifference(flux(v, p), expected);
  RecordProperty("max_abs_difference", sci(err));
  EXPECT_LT(err, 1e-12);
  p.irf.values.assign(26, 3.0);  // a box one sample wider
  EXPECT_GT(maxAbsDifference(flux(v, p), expected), 1e-3);
}

// With a source uniform over bin i0, the mean bin index of the flux is
// exactly i0 + E[shift] / w: centroid gives i0, peak and a time shift it by
// (centroid - t0) / w.
TEST(SpadIrfTest, TimeZeroModes) {
  const double w = 2e-12;
  const int i0 = 40;
  TransientVolume v = makeVolume(1, 1, 0.0, w, 100);
  v.at(0, 0, i0, 0) = 0.01f;
  SpadParams p;
  p.pde = 1.0;
  p.irf.values = {0.5, 4.0, 2.5, 1.5, 1.0, 0.7, 0.4, 0.2};  // asymmetric, peak at index 1
  p.irf.first_time_s = 3e-12;
  p.irf.sample_width_s = 1.5e-12;
  double sum = 0.0, moment = 0.0;
  for (std::size_t k = 0; k < p.irf.values.size(); ++k) {
    sum += p.irf.values[k];
    moment += p.irf.values[k] * (3e-12 + 1.5e-12 * k);
  }
  const double centroid = moment / sum, peak = 3e-12 + 1.5e-12;
  const auto meanBin = [&] {
    const std::vector<double> f = flux(v, p);
    double n = 0.0, m = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      n += f[i];
      m += f[i] * static_cast<double>(i);
    }
    return m / n;
  };
  p.irf.t0 = SpadIrf::TimeZero::Peak;
  EXPECT_DOUBLE_EQ(irfTimeZero_s(p.irf), peak);
  EXPECT_NEAR(meanBin(), i0 + (centroid - peak) / w, 1e-9);
  p.irf.t0 = SpadIrf::TimeZero::Centroid;
  EXPECT_NEAR(irfTimeZero_s(p.irf), centroid, 1e-24);
  EXPECT_NEAR(meanBin(), i0, 1e-9);
  p.irf.t0 = SpadIrf::TimeZero::Time;
  p.irf.t0_s = 1e-12;
  EXPECT_NEAR(meanBin(), i0 + (centroid - 1e-12) / w, 1e-9);
}

TEST(SpadIrfTest, KernelsConserveAndMatchTheGaussianMoments) {
  // The exact Gaussian kernel's variance is sigma^2 + 1/6 (source and
  // detection uniform in their bins; the periodic correction is
  // exp(-2 pi^2 sigma^2) ~ 1e-77 at 3 bins) up to its 6-sigma end; the 64-point
  // quadrature this replaced was 2e-5 off.
  const BinKernel k = gaussianKernel(3.0, 1.0);
  double s = 0.0, m2 = 0.0;
  for (std::size_t j = 0; j < k.weights.size(); ++j) {
    const double d = k.first + static_cast<double>(j);
    s += k.weights[j];
    m2 += d * d * k.weights[j];
  }
  EXPECT_NEAR(s, 1.0, 1e-14);
  EXPECT_NEAR(m2, 9.0 + 1.0 / 6.0, 1e-7);  // the kernel ends 6 sigma out: 4e-8
}

}  // namespace
}  // namespace tofsim::sensors
