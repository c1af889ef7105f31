// The SPAD's estimators beside the peak (sensors/src/SpadEstimators): the
// log-matched filter recovers a known depth under Poisson noise better than
// the peak (statistical, fixed seed), first / strongest / last returns of a
// two-return histogram, and the detection confidence; the filter's
// correlation, by blocks or from each counted bin, bit for bit the plain sum.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "KernelCorrelation.h"
#include "PeakDepth.h"
#include "SpadEstimators.h"
#include "tofsim/sensors/Random.h"
#include "tofsim/sensors/TimeKernel.h"

namespace tofsim::sensors {
namespace {

TimeAxis testAxis(int32_t bins) {
  TimeAxis axis;
  axis.start_s = 10e-9;
  axis.bin_width_s = 10e-12;
  axis.bins = bins;
  return axis;
}

// Expected counts A k(i - tau) + B of an arrival in bin tau.
std::vector<double> expected(const BinKernel& k, int32_t K, int32_t tau, double A, double B) {
  std::vector<double> lambda(static_cast<std::size_t>(K), B);
  for (std::size_t j = 0; j < k.weights.size(); ++j) {
    const int32_t i = tau + k.first + static_cast<int32_t>(j);
    if (i >= 0 && i < K) lambda[i] += A * k.weights[j];
  }
  return lambda;
}

std::vector<double> poissonDraw(const std::vector<double>& lambda, Rng& rng) {
  std::vector<double> h(lambda.size());
  for (std::size_t i = 0; i < h.size(); ++i) h[i] = static_cast<double>(rng.poisson(lambda[i]));
  return h;
}

// The correlation (KernelCorrelation.h) against the plain double loop over
// counted bins i and kernel taps j in that order (the estimator's before it),
// bit for bit: dense histograms (the blocks, K not a multiple of a block) and
// sparse ones (the scatter), kernels reaching before and after the window.
TEST(SpadEstimatorsTest, CorrelationIsThePlainSumBitForBit) {
  Rng rng(5, 0);
  for (const int32_t K : {1, 7, 300, 1001}) {
    for (const int32_t first : {-40, -3, 0, 5}) {
      for (const double fill : {1.0, 0.2, 0.0}) {  // dense, sparse, one count
        SCOPED_TRACE(std::to_string(K) + " bins, first " + std::to_string(first) + ", fill " +
                     std::to_string(fill));
        std::vector<double> h(static_cast<std::size_t>(K), 0.0);
        for (double& v : h) v = rng.uniform() < fill ? static_cast<double>(rng.poisson(20.0)) : 0.0;
        h[static_cast<std::size_t>(K / 2)] = 3.0;
        std::vector<double> a(77), b(77);
        for (std::size_t j = 0; j < a.size(); ++j) {
          a[j] = rng.uniform();
          b[j] = std::exp(-0.1 * static_cast<double>(j)) * rng.uniform();
        }
        std::vector<double> pa(h.size(), 0.0), pb(h.size(), 0.0);
        for (int32_t i = 0; i < K; ++i) {
          if (h[i] == 0.0) continue;
          for (int32_t j = 0; j < static_cast<int32_t>(a.size()); ++j) {
            const int32_t tau = i - first - j;
            if (tau < 0 || tau >= K) continue;
            pa[tau] += h[i] * a[j];
            pb[tau] += h[i] * b[j];
          }
        }
        for (const bool portable : {false, true}) {  // AVX2 where the CPU has it, and not
          std::vector<double> ca, cb, scratch;
          detail::correlateWithTwo(h, first, a, b, ca, cb, scratch, portable);
          EXPECT_EQ(ca, pa) << portable;
          EXPECT_EQ(cb, pb) << portable;
        }
      }
    }
  }
}

TEST(SpadEstimatorsTest, MatchedFilterBeatsThePeakUnderNoise) {
  // A wide response with a long diffusion tail (60 ps sigma, half of the
  // detections 300 ps later on average) in 10 ps bins, 150 signal counts on 2
  // background counts per bin.
  const int32_t K = 300, tau = 100;
  const TimeAxis axis = testAxis(K);
  const BinKernel kernel = gaussianTailKernel(60e-12, 0.5, 300e-12, axis.bin_width_s);
  const SpadEstimator estimator(kernel, axis, 5.0);
  const std::vector<double> lambda = expected(kernel, K, tau, 150.0, 2.0);
  const double truth = axis.depthOf_m(axis.start_s + (tau + 0.5) * axis.bin_width_s);
  const double binDepth = axis.depthOf_m(axis.bin_width_s);
  Rng rng(11, 24);
  SpadEstimator::Scratch scratch;
  const int trials = 400;
  double sumMatched = 0.0, sq = 0.0, sqPeak = 0.0;
  for (int t = 0; t < trials; ++t) {
    const std::vector<double> h = poissonDraw(lambda, rng);
    const double matched = (estimator.estimate(h, scratch).matched_depth_m - truth) / binDepth;
    const double peak = (peakDepth_m(h, axis) - truth) / binDepth;
    sumMatched += matched;
    sq += matched * matched;
    sqPeak += peak * peak;
  }
  const double mean = sumMatched / trials;
  const double rms = std::sqrt(sq / trials), rmsPeak = std::sqrt(sqPeak / trials);
  const double sd = std::sqrt(std::max(0.0, rms * rms - mean * mean));
  std::printf("matched filter: bias %.3f bins, RMS %.3f bins; peak RMS %.3f bins\n", mean, rms,
              rmsPeak);
  // Unbiased within 4 standard errors plus a tenth of a bin (the parabola).
  const double bound = 4.0 * sd / std::sqrt(trials) + 0.1;
  EXPECT_LT(std::fabs(mean), bound);
  EXPECT_LT(rms, 0.5 * rmsPeak);
  EXPECT_LT(rms, 2.0);  // the Cramer-Rao scale: sigma 6 bins / sqrt(150 counts) ~ 0.5 bin

  // A filter with the wrong response (the Gaussian part only) is biased by
  // the tail it ignores: the test sees a mis-parametrised kernel.
  const SpadEstimator wrong(gaussianKernel(60e-12, axis.bin_width_s), axis, 5.0);
  double sumWrong = 0.0;
  for (int t = 0; t < trials; ++t) {
    sumWrong +=
        (wrong.estimate(poissonDraw(lambda, rng), scratch).matched_depth_m - truth) / binDepth;
  }
  std::printf("without the tail: bias %.3f bins (bound %.3f)\n", sumWrong / trials, bound);
  EXPECT_GT(std::fabs(sumWrong / trials), 3.0 * bound);
}

TEST(SpadEstimatorsTest, FirstStrongestAndLastReturnsOfTwoReturns) {
  // A partial hit on a near edge (bin 60, 150 counts) and the wall behind
  // (bin 200, 400 counts), 1 background count per bin, 20 ps sigma.
  const int32_t K = 300;
  const TimeAxis axis = testAxis(K);
  const BinKernel kernel = gaussianKernel(20e-12, axis.bin_width_s);
  // 6 sigma: at 1 count per bin Poisson's skew gives 5 sigma about one false
  // return per 10^4 bins (the normal approximation's 3e-7 is optimistic).
  const SpadEstimator estimator(kernel, axis, 6.0);
  std::vector<double> lambda = expected(kernel, K, 60, 150.0, 1.0);
  const std::vector<double> far = expected(kernel, K, 200, 400.0, 0.0);
  for (int32_t i = 0; i < K; ++i) lambda[i] += far[i];
  const auto depthOfBin = [&](int32_t b) {
    return axis.depthOf_m(axis.start_s + (b + 0.5) * axis.bin_width_s);
  };
  const double bin = axis.depthOf_m(axis.bin_width_s);
  SpadEstimator::Scratch scratch;
  Rng rng(5, 9);
  for (int t = 0; t < 50; ++t) {
    const SpadEstimates e = estimator.estimate(poissonDraw(lambda, rng), scratch);
    ASSERT_EQ(e.returns, 2);
    EXPECT_NEAR(e.first.depth_m, depthOfBin(60), 1.0 * bin);  // ~4 sigma of 2 bins / sqrt(150)
    EXPECT_NEAR(e.last.depth_m, depthOfBin(200), 1.0 * bin);
    EXPECT_EQ(e.strongest.depth_m, e.last.depth_m);
    EXPECT_NEAR(e.first.intensity, 150.0, 4.0 * std::sqrt(150.0));
    EXPECT_NEAR(e.last.intensity, 400.0, 4.0 * std::sqrt(400.0));
    EXPECT_GT(e.confidence, 0.999);
  }
  // Background alone: no return, and a confidence that is not certainty.
  int returns = 0;
  double confidence = 0.0;
  for (int t = 0; t < 200; ++t) {
    const SpadEstimates e =
        estimator.estimate(poissonDraw(std::vector<double>(K, 1.0), rng), scratch);
    returns += e.returns;
    confidence += e.confidence / 200.0;
  }
  std::printf("background only: %d returns in 200 pixels, mean confidence %.3f\n", returns,
              confidence);
  EXPECT_LE(returns, 2);  // of 60,000 bins
  EXPECT_LT(confidence, 0.5);
  EXPECT_TRUE(std::isnan(estimator.estimate(std::vector<double>(K, 0.0), scratch).matched_depth_m));
}

// The confidence as a test of the pixel's counts against its background:
// background alone (a dark-count rate where most bins are empty and the
// median is 0, and daylight ambient) gives P(confidence > c) <= 1 - c, the
// law sensors/README.md states (about 0.5 or below for noise), each count
// within 4 binomial sigmas; a return of 120 counts (10 sigma over the 3-count background of its
// window of ~17 bins) gives > 0.999 in every pixel. A confidence that ignores the background
// (or reads it as the median, 0 at dark-count rates) puts most background-only
// pixels above 0.99.
TEST(SpadEstimatorsTest, ConfidenceSeparatesBackgroundFromReturns) {
  const int32_t K = 400;
  const TimeAxis axis = testAxis(K);
  const BinKernel kernel = gaussianKernel(20e-12, axis.bin_width_s);
  const SpadEstimator estimator(kernel, axis, 5.0);
  SpadEstimator::Scratch scratch;
  Rng rng(11, 3);
  const int pixels = 1000;
  for (double background : {0.02, 3.0}) {
    const std::vector<double> flat(static_cast<std::size_t>(K), background);
    std::vector<double> noise;
    for (int t = 0; t < pixels; ++t) {
      noise.push_back(estimator.estimate(poissonDraw(flat, rng), scratch).confidence);
    }
    for (double c : {0.5, 0.9, 0.99}) {
      int above = 0;
      for (double v : noise) above += v > c ? 1 : 0;
      const double bound = pixels * (1.0 - c), sigma = std::sqrt(bound * c);
      std::printf("background %.2f / bin: %d of %d pixels above %.2f (bound %.0f)\n", background,
                  above, pixels, c, bound);
      EXPECT_LE(above, bound + 4.0 * sigma + 1.0) << background << " " << c;
    }
    const std::vector<double> lambda = expected(kernel, K, 200, 120.0, background);
    double lowest = 1.0;
    for (int t = 0; t < 200; ++t) {
      lowest = std::min(lowest, estimator.estimate(poissonDraw(lambda, rng), scratch).confidence);
    }
    std::printf("background %.2f / bin, 120-count return: lowest confidence %.6f\n", background,
                lowest);
    EXPECT_GT(lowest, 0.999) << background;
  }
}

}  // namespace
}  // namespace tofsim::sensors
