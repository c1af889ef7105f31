// The temporal-response stage (TemporalResponse.h, temporal_response.glsl):
// a class's light through its kernel against closed forms. An impulse (a
// unit of light in one bin, uniform across it) through the exponential
// filter gives the bin integrals of (1/tau) exp(-t/tau) convolved with that
// bin's box, written here as the double integral in closed form; energy is
// kept (the bins plus the light reported past the axis equal the input);
// a Gaussian moves the mean by its mean exactly and adds its variance (plus
// the 1/6 bin^2 of two bin boxes); a table of an exponential reproduces it.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "tofsim/physics/FootprintBuffer.h"
#include "tofsim/physics/TemporalResponse.h"

namespace tofsim::physics {
namespace {

constexpr double kBin_s = 10e-12;

// A difference buffer holding one unit of light (per channel `energy`) in bin k.
std::vector<double> impulse(int32_t bins, int32_t k, const glm::vec3& energy = glm::vec3(1.0f)) {
  std::vector<double> diff(static_cast<std::size_t>(bins) * 3, 0.0);
  for (int o = 0; o < 3; ++o) {
    if (k + o >= bins) break;
    for (int c = 0; c < 3; ++c) {
      diff[static_cast<std::size_t>(k + o) * 3 + c] += (o == 1 ? -2.0 : 1.0) * energy[c];
    }
  }
  return diff;
}

// int_{bin m} dt int_{bin 0} ds (1/tau) exp(-(t - s)/tau) [t > s], bins of 1:
// the exponential convolved with the source bin's box, in closed form.
double exponentialBinIntegral(double tau, int m) {
  if (m < 0) return 0.0;
  if (m == 0) return 1.0 - tau * (1.0 - std::exp(-1.0 / tau));  // int_0^1 (1 - e^(-t/tau)) dt
  const double overSource = tau * (std::exp(1.0 / tau) - 1.0);   // int_0^1 e^(s/tau) ds
  return overSource * (std::exp(-m / tau) - std::exp(-(m + 1) / tau));  // times int_m^(m+1) e^(-t/tau)/tau
}

struct Output {
  std::vector<float> histogram;
  double past = 0.0;
};

Output run(std::vector<double> diff, int32_t bins, const ResponseTaps& taps) {
  Output out{std::vector<float>(static_cast<std::size_t>(bins) * 3, 0.0f), 0.0};
  out.past = applyResponse(diff.data(), bins, 0, taps, out.histogram.data());
  return out;
}

TEST(TemporalResponseTest, ExponentialImpulseGivesTheClosedFormBinIntegrals) {
  const int32_t bins = 600, k = 40;
  for (const double lifetime_s : {3e-12, 10e-12, 250e-12, 2.5e-9}) {
    for (const double fraction : {1.0, 0.6}) {
      ResponseKernel kernel;
      kernel.lifetime_s = lifetime_s;
      kernel.fraction = fraction;
      const Output out = run(impulse(bins, k), bins, responseTaps(kernel, kBin_s));
      const double tau = lifetime_s / kBin_s;
      for (int32_t n = 0; n < bins; ++n) {
        const double expected =
            fraction * exponentialBinIntegral(tau, n - k) + (n == k ? 1.0 - fraction : 0.0);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(out.histogram[static_cast<std::size_t>(n) * 3 + c], expected,
                      2e-7 * expected + 1e-30)
              << "lifetime " << lifetime_s << " s, bin " << n;
        }
      }
      // Past the axis: int_T^inf dt int_k^(k+1) ds, in closed form, per channel.
      const double past = fraction * tau * (std::exp(1.0 / tau) - 1.0) * std::exp(-(bins - k) / tau);
      EXPECT_NEAR(out.past, 3.0 * past, 1e-9 * (3.0 * past) + 1e-12) << lifetime_s;
    }
  }
}

TEST(TemporalResponseTest, ADepositedSpikeIsTheImpulseOfItsBin) {
  // A point sample (a footprint kernel of widths 0) deposited into a class's
  // difference buffer is a unit in point sampling's bin.
  const int32_t bins = 200;
  std::vector<double> diff(static_cast<std::size_t>(bins) * 3, 0.0);
  depositFootprint(diff.data(), bins, vec3(57.3f, 0.0f, 0.0f), vec3(1.0f, 2.0f, 0.5f));
  ResponseKernel kernel;
  kernel.lifetime_s = 80e-12;
  const ResponseTaps taps = responseTaps(kernel, kBin_s);
  const Output spike = run(diff, bins, taps);
  const Output unit = run(impulse(bins, 57, glm::vec3(1.0f, 2.0f, 0.5f)), bins, taps);
  EXPECT_EQ(spike.histogram, unit.histogram);
}

TEST(TemporalResponseTest, EnergyIsKeptAndWhatPassesTheAxisIsReported) {
  // Several footprint kernels (spikes, narrow, hundreds of bins, across the
  // axis's end) into one class. On an axis long enough for every kernel's
  // tail the bins sum to the light that went in; on the short axis the light
  // reported past it is what the long axis holds past the short one's end.
  const int32_t bins = 400, longBins = 3400;
  std::vector<double> diff(static_cast<std::size_t>(bins) * 3, 0.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> centre(2.0f, 420.0f), width(0.0f, 150.0f), e(0.1f, 2.0f);
  for (int i = 0; i < 20; ++i) {
    const float a = width(rng), b = width(rng) * 0.3f;
    depositFootprint(diff.data(), bins, vec3(centre(rng), std::max(a, b), std::min(a, b)),
                     vec3(e(rng), e(rng), e(rng)));
  }
  // The light on the short axis as bin integrals, and the same light as the
  // second differences of a long axis (zeros after the short one's end).
  double in = 0.0;
  std::vector<double> x(static_cast<std::size_t>(bins) * 3);
  double slope[3] = {}, value[3] = {};
  for (std::size_t k = 0; k < x.size(); ++k) {
    slope[k % 3] += diff[k];
    value[k % 3] += slope[k % 3];
    x[k] = value[k % 3];
    in += x[k];
  }
  std::vector<double> longDiff(static_cast<std::size_t>(longBins) * 3, 0.0);
  for (std::size_t k = 0; k < x.size() + 6; ++k) {
    const auto at = [&](std::size_t i) { return i < x.size() ? x[i] : 0.0; };
    longDiff[k] = at(k) - 2.0 * (k >= 3 ? at(k - 3) : 0.0) + (k >= 6 ? at(k - 6) : 0.0);
  }
  std::vector<ResponseKernel> kernels(3);
  kernels[0].lifetime_s = 500e-12;
  kernels[0].fraction = 0.7;
  kernels[1].model = ResponseModel::Gaussian;
  kernels[1].mean_s = 300e-12;
  kernels[1].sigma_s = 80e-12;
  kernels[2].model = ResponseModel::Table;
  kernels[2].tableDelay_s = {0.0, 100e-12, 400e-12, 1e-9};
  kernels[2].tableWeight = {0.0, 3.0, 1.0, 0.0};
  for (const ResponseKernel& kernel : kernels) {
    const ResponseTaps taps = responseTaps(kernel, kBin_s);
    const Output out = run(diff, bins, taps);
    const Output all = run(longDiff, longBins, taps);
    double sum = 0.0, longSum = 0.0, pastEnd = 0.0;
    for (const float v : out.histogram) sum += v;
    for (std::size_t k = 0; k < all.histogram.size(); ++k) {
      longSum += all.histogram[k];
      if (k >= x.size()) pastEnd += all.histogram[k];
    }
    EXPECT_NEAR(longSum, in, 1e-6 * in);  // energy kept
    EXPECT_LT(all.past, 1e-9 * in);
    EXPECT_GT(out.past, 0.01 * in);  // the kernels reach past the short axis
    EXPECT_NEAR(out.past, pastEnd, 1e-6 * in);
    EXPECT_NEAR(sum + out.past, in, 1e-6 * in);
  }
}

// Mean and variance of the output, in bins relative to `k`, with its mass.
struct Moments {
  double mass = 0.0, mean = 0.0, variance = 0.0;
};
Moments momentsOf(const std::vector<float>& histogram, int32_t k) {
  Moments m;
  double first = 0.0, second = 0.0;
  for (std::size_t n = 0; n < histogram.size() / 3; ++n) {
    const double v = histogram[n * 3], d = static_cast<double>(n) - k;
    m.mass += v;
    first += v * d;
    second += v * d * d;
  }
  m.mean = first / m.mass;
  m.variance = second / m.mass - m.mean * m.mean;
  return m;
}

TEST(TemporalResponseTest, GaussianMovesTheMeanByItsMeanAndAddsItsVariance) {
  // Hat functions reproduce linear functions, so the output's mean in bin
  // indices is the input bin plus the kernel's mean exactly; its variance is
  // the kernel's plus 1/6 (the input's bin box and the output's binning).
  const int32_t bins = 1000, k = 100;
  for (const double sigma_ps : {25.0, 40.0, 120.0}) {
    for (const double fraction : {1.0, 0.4}) {
      ResponseKernel kernel;
      kernel.model = ResponseModel::Gaussian;
      kernel.mean_s = 1.234e-9;
      kernel.sigma_s = sigma_ps * 1e-12;
      kernel.fraction = fraction;
      const ResponseTaps taps = responseTaps(kernel, kBin_s);
      const Output out = run(impulse(bins, k), bins, taps);
      const Moments m = momentsOf(out.histogram, k);
      const double mu = 123.4, sigma = sigma_ps / 10.0;
      const double mean = fraction * mu;
      const double variance = fraction * (sigma * sigma + mu * mu) - mean * mean + fraction / 6.0;
      EXPECT_NEAR(m.mass, 1.0, 1e-6);
      EXPECT_NEAR(m.mean, mean, 1e-4) << sigma_ps;
      EXPECT_NEAR(m.variance, variance, 1e-4 * variance) << sigma_ps;
      EXPECT_NEAR(out.past, 0.0, 1e-12);
    }
  }
  // Truncated at zero delay and renormalised: still the whole light.
  ResponseKernel early;
  early.model = ResponseModel::Gaussian;
  early.mean_s = 5e-12;
  early.sigma_s = 20e-12;
  const ResponseTaps taps = responseTaps(early, kBin_s);
  EXPECT_EQ(taps.delay, 0);
  EXPECT_NEAR(momentsOf(run(impulse(bins, k), bins, taps).histogram, k).mass, 1.0, 1e-6);
}

TEST(TemporalResponseTest, ATableOfAnExponentialReproducesIt) {
  const double lifetime_s = 200e-12;
  ResponseKernel table;
  table.model = ResponseModel::Table;
  for (int i = 0; i <= 4000; ++i) {  // 0.05 bins apart, 10 lifetimes
    const double t = i * 0.5e-12;
    table.tableDelay_s.push_back(t);
    table.tableWeight.push_back(std::exp(-t / lifetime_s));
  }
  ResponseKernel exponential;
  exponential.lifetime_s = lifetime_s;
  const int32_t bins = 300, k = 10;
  const Output fromTable = run(impulse(bins, k), bins, responseTaps(table, kBin_s));
  const Output exact = run(impulse(bins, k), bins, responseTaps(exponential, kBin_s));
  const double peak = exponentialBinIntegral(20.0, 1);
  for (int32_t n = 0; n < 200; ++n) {
    EXPECT_NEAR(fromTable.histogram[static_cast<std::size_t>(n) * 3],
                exact.histogram[static_cast<std::size_t>(n) * 3], 1e-3 * peak)
        << n;
  }
}

TEST(TemporalResponseTest, KernelsOutsideTheirRangesAreRefused) {
  ResponseKernel k;
  k.lifetime_s = -1e-9;
  EXPECT_THROW(responseTaps(k, kBin_s), std::invalid_argument);
  k.lifetime_s = 1e-9;
  k.fraction = 1.5;
  EXPECT_THROW(responseTaps(k, kBin_s), std::invalid_argument);
  ResponseKernel g;
  g.model = ResponseModel::Gaussian;
  g.mean_s = 1e-9;
  g.sigma_s = 0.0;
  EXPECT_THROW(responseTaps(g, kBin_s), std::invalid_argument);
  g.sigma_s = 1e-6;  // 16 sigma = 1.6 million bins
  EXPECT_THROW(responseTaps(g, kBin_s), std::invalid_argument);
  ResponseKernel t;
  t.model = ResponseModel::Table;
  t.tableDelay_s = {2e-12, 1e-12};
  t.tableWeight = {1.0, 1.0};
  EXPECT_THROW(responseTaps(t, kBin_s), std::invalid_argument);
  t.tableDelay_s = {1e-12, 2e-12};
  t.tableWeight = {0.0, 0.0};
  EXPECT_THROW(responseTaps(t, kBin_s), std::invalid_argument);
}

}  // namespace
}  // namespace tofsim::physics
