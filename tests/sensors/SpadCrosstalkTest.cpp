// SPAD crosstalk on the streamed fast path (SpadCrosstalk.h): a dark pixel
// next to a bright one counts the bright one's stops thinned by p, in the
// same bin (prompt) or delayed by the exponential kernel (free-running:
// wrapped into the next period); 4 neighbours leave the diagonal dark, 8 do
// not; an exact avalanche-by-avalanche simulation of a lit 3 x 3 array
// agrees; and the bytes do not depend on spans or threads.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <iostream>
#include <memory>
#include <vector>

#include "CrosstalkOracle.h"
#include "TestVolumes.h"
#include "support/ChiSquare.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {
namespace {

using test::addTwoSample;
using test::againstMultinomial;
using test::array;
using test::litPixel;
using test::makeVolume;
using test::TwoSample;
using tofsim::test::chiSquareQuantile;
using tofsim::test::pearson;

constexpr double kW = 10e-12;  // TDC and render bin width
constexpr int32_t kBins = 80;
constexpr int32_t kSide = 5, kA = 2;  // a 5 x 5 image, the bright pixel A at its centre

using Flux = std::function<std::vector<double>(int32_t y, int32_t x)>;

TransientVolume volumeOf(int32_t w, int32_t h, int32_t bins, const Flux& flux) {
  TransientVolume v = makeVolume(w, h, 0.0, kW, bins);
  for (int32_t y = 0; y < h; ++y) {
    for (int32_t x = 0; x < w; ++x) {
      const std::vector<double> f = flux(y, x);
      for (int32_t t = 0; t < bins; ++t) v.at(y, x, t, 0) = static_cast<float>(f[t]);
    }
  }
  return v;
}

// A's light: a broad return over bins 10-39 (1.29 photons per cycle in all, P_det 0.72).
std::vector<double> brightReturn() {
  std::vector<double> f(kBins, 0.0);
  for (int32_t t = 10; t < 40; ++t) f[t] = static_cast<float>(0.045 * (1.0 + std::sin(0.2 * t)));
  return f;
}

Flux onlyA(const std::vector<double>& a) {
  return
      [a](int32_t y, int32_t x) { return y == kA && x == kA ? a : std::vector<double>(a.size()); };
}

SpadParams crosstalk(double p, CrosstalkNeighbours n, double delay_s = 0.0) {
  SpadParams s;
  s.cycles = 1'000'000;
  s.pde = 1.0;
  s.crosstalk_probability = p;
  s.crosstalk_neighbours = n;
  s.crosstalk_delay_s = delay_s;
  return s;
}

// The summed histograms of the pixels at these (dy, dx) from A.
std::vector<double> around(const std::vector<SensorOutput>& outs,
                           const std::vector<std::array<int32_t, 2>>& offsets) {
  const SensorOutput& c = array(outs, "spad_counts");
  std::vector<double> h(kBins, 0.0);
  for (const auto& [dy, dx] : offsets) {
    const std::size_t px = static_cast<std::size_t>((kA + dy) * kSide + kA + dx);
    for (int32_t t = 0; t < kBins; ++t) h[t] += c.data[px * kBins + t];
  }
  return h;
}

const std::vector<std::array<int32_t, 2>> kEdge = {{-1, 0}, {0, -1}, {0, 1}, {1, 0}};
const std::vector<std::array<int32_t, 2>> kDiagonal = {{-1, -1}, {-1, 1}, {1, -1}, {1, 1}};

std::vector<double> scaled(std::vector<double> v, double s) {
  for (double& x : v) x *= s;
  return v;
}

// A's first-stop law P_A,i of its own light (its flux as the volume holds it).
std::vector<double> stopsOfA() { return firstPhotonProbabilities(brightReturn()); }

// B dark (no light, no dark counts), next to A: B's only avalanches are
// copies of A's one stop per cycle, so h_B ~ Multinomial(N, p P_A,i)
// (shared/research/detector-models.md 1.2), for any p.
TEST(SpadCrosstalkTest, DarkNeighbourCountsTheBrightPixelsStopsThinnedByP) {
  for (const double p : {0.01, 0.1}) {
    const SpadParams s = crosstalk(p, CrosstalkNeighbours::Four);
    const std::vector<SensorOutput> outs =
        runSpad(volumeOf(kSide, kSide, kBins, onlyA(brightReturn())), s, 5);
    const std::vector<double> hB = around(outs, kEdge);
    const double draws = 4.0 * static_cast<double>(s.cycles);
    const auto fit = againstMultinomial(hB, scaled(stopsOfA(), p), draws);
    std::cout << "p_xt " << p << ": chi2 " << fit.statistic << " / " << fit.dof << " dof\n";
    EXPECT_LT(fit.statistic, chiSquareQuantile(fit.dof, 3.09)) << "p " << p;
    // It can fail: a p 10 % off, or no crosstalk, is rejected.
    const auto off = againstMultinomial(hB, scaled(stopsOfA(), 1.1 * p), draws);
    EXPECT_GT(off.statistic, chiSquareQuantile(off.dof, 3.09)) << "p " << p;
    SpadParams none = s;
    none.crosstalk_probability = 0.0;
    const auto zero = againstMultinomial(
        around(runSpad(volumeOf(kSide, kSide, kBins, onlyA(brightReturn())), none, 5), kEdge),
        scaled(stopsOfA(), p), draws);
    EXPECT_GT(zero.statistic, chiSquareQuantile(zero.dof, 3.09)) << "p " << p;
    // 4 neighbours: the diagonal and the pixels two away stay dark.
    for (const double v : around(outs, kDiagonal)) EXPECT_EQ(v, 0.0);
    for (const double v : around(outs, {{-2, 0}, {0, 2}, {2, -2}})) EXPECT_EQ(v, 0.0);
  }
}

// 8 neighbours: the diagonal pixels get A's stops thinned by p as well.
TEST(SpadCrosstalkTest, EightNeighboursReachTheDiagonal) {
  const double p = 0.05;
  const SpadParams s = crosstalk(p, CrosstalkNeighbours::Eight);
  const std::vector<SensorOutput> outs =
      runSpad(volumeOf(kSide, kSide, kBins, onlyA(brightReturn())), s, 6);
  const double draws = 4.0 * static_cast<double>(s.cycles);
  for (const auto* ring : {&kEdge, &kDiagonal}) {
    const auto fit = againstMultinomial(around(outs, *ring), scaled(stopsOfA(), p), draws);
    EXPECT_LT(fit.statistic, chiSquareQuantile(fit.dof, 3.09));
  }
  for (const double v : around(outs, {{-2, 0}, {2, 2}, {0, -2}})) EXPECT_EQ(v, 0.0);
}

// Delayed crosstalk: A lit in one bin i0 (its stop there with probability P
// = 1 - e^-f), B's arrivals p P kappa_(i - i0), kappa the exponential delay of
// mean tau (in bins) for an avalanche uniform in its bin: kappa_0 = 1 -
// tau (1 - e^(-1/tau)), kappa_d = tau (1 - e^(-1/tau)) (e^(1/tau) - 1) e^(-d/tau)
// for d >= 1; those past the window are lost.
std::vector<double> delayedLaw(double p, double P, int32_t i0, double tau) {
  std::vector<double> law(kBins, 0.0);
  const double a = 1.0 - std::exp(-1.0 / tau);
  law[i0] = p * P * (1.0 - tau * a);
  for (int32_t d = 1; i0 + d < kBins; ++d)
    law[i0 + d] = p * P * tau * a * (std::exp(1.0 / tau) - 1.0) * std::exp(-d / tau);
  return law;
}

TEST(SpadCrosstalkTest, DelayedCrosstalkFollowsTheExponentialKernel) {
  const int32_t i0 = 30;
  const double f = static_cast<float>(0.3), p = 0.1, tau = 6.0;  // tau in bins: 60 ps
  std::vector<double> a(kBins, 0.0);
  a[i0] = f;
  const SpadParams s = crosstalk(p, CrosstalkNeighbours::Four, tau * kW);
  const std::vector<double> hB =
      around(runSpad(volumeOf(kSide, kSide, kBins, onlyA(a)), s, 7), kEdge);
  for (int32_t t = 0; t < i0; ++t) EXPECT_EQ(hB[t], 0.0) << t;  // nothing before A's light
  const double draws = 4.0 * static_cast<double>(s.cycles), P = -std::expm1(-f);
  const auto fit = againstMultinomial(hB, delayedLaw(p, P, i0, tau), draws);
  std::cout << "delayed: chi2 " << fit.statistic << " / " << fit.dof << " dof\n";
  EXPECT_LT(fit.statistic, chiSquareQuantile(fit.dof, 3.09));
  // It can fail: a delay 10 % longer, or prompt crosstalk, is rejected.
  const auto longer = againstMultinomial(hB, delayedLaw(p, P, i0, 1.1 * tau), draws);
  EXPECT_GT(longer.statistic, chiSquareQuantile(longer.dof, 3.09));
  std::vector<double> prompt(kBins, 0.0);
  prompt[i0] = p * P;
  const auto same = againstMultinomial(hB, prompt, draws);
  EXPECT_GT(same.statistic, 1e3);
}

// Free-running, no dead time: A fires in bin i with probability q_i = 1 -
// e^(-f_i) in every period, so a dark B fires there with probability p q_i
// exactly (delayed: p sum_j q_j kappa_((i - j) mod K), the delay wrapping
// into the next period), each bin's count Binomial(N, pi_i). Chi-square of
// the K independent binomials; a delay that does not wrap (arrivals past the
// period lost, as in synchronous mode) is rejected.
double binomialChiSquare(const std::vector<double>& h, const std::vector<double>& pi, double n) {
  double x2 = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double e = n * pi[i];
    x2 += (h[i] - e) * (h[i] - e) / (e * (1.0 - pi[i]));
  }
  return x2;
}

TEST(SpadCrosstalkTest, FreeRunningDarkNeighbourCountsPTimesTheBrightPixelsDetections) {
  const int32_t i0 = kBins - 8;  // near the end: a delayed arrival wraps
  const double f = static_cast<float>(0.4), p = 0.1, tau = 6.0;
  std::vector<double> a(kBins, static_cast<float>(0.01));
  a[i0] = f;
  SpadParams s = crosstalk(p, CrosstalkNeighbours::Four, tau * kW);
  s.mode = SpadMode::FreeRunning;
  const double n = 4.0 * static_cast<double>(s.cycles);
  const std::vector<double> hB =
      around(runSpad(volumeOf(kSide, kSide, kBins, onlyA(a)), s, 8), kEdge);
  // kappa_d as in delayedLaw (d = 0 .. 2K: the kernel's 14 tau reach past K).
  const double e = 1.0 - std::exp(-1.0 / tau);
  const auto kappa = [&](int32_t d) {
    return d == 0 ? 1.0 - tau * e : tau * e * (std::exp(1.0 / tau) - 1.0) * std::exp(-d / tau);
  };
  std::vector<double> wrapped(kBins, 0.0), cut(kBins, 0.0);
  for (int32_t j = 0; j < kBins; ++j) {
    const double q = -std::expm1(-a[j]);
    for (int32_t d = 0; d < 2 * kBins; ++d) {
      wrapped[(j + d) % kBins] += p * q * kappa(d);
      if (j + d < kBins) cut[j + d] += p * q * kappa(d);
    }
  }
  const double x2 = binomialChiSquare(hB, wrapped, n);
  std::cout << "free-running: chi2 " << x2 << " / " << kBins << " dof\n";
  EXPECT_LT(x2, chiSquareQuantile(kBins, 3.09));
  EXPECT_GT(binomialChiSquare(hB, cut, n), chiSquareQuantile(kBins, 3.09));
  EXPECT_GT(binomialChiSquare(hB, scaled(wrapped, 1.05), n), chiSquareQuantile(kBins, 3.09));
}

// The exact oracle: a 3 x 3 array, every pixel lit (returns at different
// times and heights, so each pixel's neighbours' stops fall inside its own),
// synchronous, prompt crosstalk, p = 0.02. Fast path and oracle drawn
// N cycles each; two-sample chi-square over every pixel's bins and its
// "no stop" cell (cells merged to >= 20 counts). First order leaves out
// O(p^2) (chains, back-triggering): at p = 0.02 below the noise of 2 10^5
// cycles; 4 neighbours in the fast path for the oracle's 8, or no crosstalk,
// are rejected.
TEST(SpadCrosstalkTest, ALitArrayAgreesWithTheExactAvalancheOracle) {
  constexpr int32_t kSide3 = 3, kBins3 = 40;
  constexpr int64_t kCycles = 200'000;
  const double p = 0.02;
  const Flux lit = [](int32_t y, int32_t x) { return litPixel(y, x, kBins3); };
  test::ArrayOracle oracle{kSide3, kSide3, kBins3, true, p, {}};
  for (int32_t y = 0; y < kSide3; ++y)
    for (int32_t x = 0; x < kSide3; ++x) oracle.flux.push_back(litPixel(y, x, kBins3));
  const std::vector<std::vector<double>> exact = oracle.run(kCycles, 11);

  const auto compare = [&](double fastP, CrosstalkNeighbours n) {
    SpadParams s = crosstalk(fastP, n);
    s.cycles = kCycles;
    const std::vector<SensorOutput> outs = runSpad(volumeOf(kSide3, kSide3, kBins3, lit), s, 12);
    const SensorOutput& c = array(outs, "spad_counts");
    TwoSample t;
    for (std::size_t k = 0; k < exact.size(); ++k) {
      const std::vector<double> fast(c.data.begin() + k * kBins3,
                                     c.data.begin() + (k + 1) * kBins3);
      addTwoSample(fast, exact[k], kCycles, t);
    }
    return t;
  };
  const TwoSample same = compare(p, CrosstalkNeighbours::Eight);
  std::cout << "oracle: chi2 " << same.statistic << " / " << same.dof << " dof\n";
  EXPECT_LT(same.statistic, chiSquareQuantile(same.dof, 3.09));
  const TwoSample four = compare(p, CrosstalkNeighbours::Four);
  EXPECT_GT(four.statistic, chiSquareQuantile(four.dof, 3.09));
  const TwoSample none = compare(0.0, CrosstalkNeighbours::Eight);
  EXPECT_GT(none.statistic, chiSquareQuantile(none.dof, 3.09));
}

// Streamed in spans of any size (cutting rows, shorter and longer than the
// look-ahead and the ring) on 1 or 2 threads, both modes, delayed crosstalk:
// the bytes of the whole volume at once.
TEST(SpadCrosstalkTest, BytesDoNotDependOnSpansOrThreads) {
  constexpr int32_t kW2 = 40, kH2 = 20, kBins2 = 32;  // 800 pixels, more than the ring holds
  const Flux flux = [](int32_t y, int32_t x) {
    std::vector<double> f(kBins2, 0.001);
    f[(x * 7 + y * 3) % kBins2] += 0.05 * (1 + (x * y) % 7);
    return f;
  };
  const TransientVolume volume = volumeOf(kW2, kH2, kBins2, flux);
  for (const SpadMode mode : {SpadMode::Synchronous, SpadMode::FreeRunning}) {
    SpadParams s = crosstalk(0.05, CrosstalkNeighbours::Eight, 25e-12);
    s.cycles = 5000;
    s.mode = mode;
    s.dead_time_s = 3 * kW;
    const std::vector<float> whole = array(runSpad(volume, s, 3), "spad_counts").data;
    SpadParams off = s;
    off.crosstalk_probability = 0.0;
    EXPECT_NE(whole, array(runSpad(volume, off, 3), "spad_counts").data);
    for (const int threads : {1, 2}) {
      for (const std::size_t span :
           {std::size_t{1}, std::size_t{13}, std::size_t{40}, std::size_t{97}, std::size_t{800}}) {
        StreamOptions options;
        options.seed = 3;
        options.threads = threads;
        const auto stream = openSpad(s, shapeOf(volume), options);
        const PixelSpan all = wholeVolume(volume);
        for (std::size_t first = 0; first < shapeOf(volume).pixelCount(); first += span) {
          PixelSpan part = all;
          part.firstPixel = first;
          part.pixelCount = std::min(span, shapeOf(volume).pixelCount() - first);
          part.volume = all.volume + first * shapeOf(volume).pixelFloats();
          stream->consume(part);
        }
        const std::vector<float> streamed = array(stream->finish(nullptr), "spad_counts").data;
        ASSERT_EQ(streamed.size(), whole.size());
        EXPECT_EQ(std::memcmp(streamed.data(), whole.data(), whole.size() * sizeof(float)), 0)
            << "span " << span << ", threads " << threads;
      }
    }
  }
}

}  // namespace
}  // namespace tofsim::sensors
