// Multi-stop TDCs and dead time longer than the laser period (issue 24, item
// 5), in the event engine (SpadDetector) and through the SPAD model: unlimited
// stops with a one-bin dead time make independent Binomial(N, q_i) bins, one
// stop is the first-photon law, and a dead time of m cycles gives P / (1 +
// (m - 1) P) detections per cycle; each with a variant that must fail.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "FirstPhotonChiSquare.h"
#include "SpadEventEngine.h"
#include "TestVolumes.h"
#include "support/ChiSquare.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {
namespace {

std::vector<double> engine(const std::vector<double>& flux, uint64_t cycles, int32_t deadBins,
                           int64_t stops, uint64_t seed, uint64_t stream = 1) {
  detail::DetectorLaws laws;
  laws.deadBins = deadBins;
  laws.stops = stops;
  Rng rng(seed, stream);
  std::vector<double> h(flux.size(), 0.0);
  detail::spadEvents(flux, cycles, laws, rng, h);
  return h;
}

// Light across the cycle, q from ~0.02 to ~0.6 per bin: neighbours interact
// strongly if they are not independent.
std::vector<double> brightFlux() {
  std::vector<double> flux(24, 0.02);
  for (int t = 6; t < 18; ++t) flux[t] += 0.9 * std::exp(-0.1 * (t - 12) * (t - 12));
  return flux;
}

struct BinStatistics {
  double chiSquare = 0.0;     ///< sum over bins of (H_i - n q_i)^2 / (n q_i (1 - q_i)), H pooled
  double zCorrelation = 0.0;  ///< the sum of the neighbours' sample correlations, normalised
};

// `pixels` independent pixels of `cycles` cycles: the pooled counts against
// Binomial(pixels cycles, q_i) and the neighbours' correlations across pixels
// (each ~ N(0, 1 / pixels) and uncorrelated with the others when the bins are
// independent).
BinStatistics independence(const std::vector<double>& flux, int32_t deadBins, int64_t stops,
                           int pixels, uint64_t cycles) {
  const std::size_t K = flux.size();
  std::vector<std::vector<double>> h;
  for (int p = 0; p < pixels; ++p) h.push_back(engine(flux, cycles, deadBins, stops, 31, p));
  BinStatistics s;
  std::vector<double> mean(K, 0.0), sd(K, 0.0);
  for (std::size_t i = 0; i < K; ++i) {
    for (const auto& hp : h) mean[i] += hp[i] / pixels;
    for (const auto& hp : h) sd[i] += (hp[i] - mean[i]) * (hp[i] - mean[i]) / (pixels - 1);
    sd[i] = std::sqrt(sd[i]);
    const double q = -std::expm1(-flux[i]);
    const double n = static_cast<double>(pixels) * static_cast<double>(cycles);
    const double pooled = mean[i] * pixels;
    s.chiSquare += (pooled - n * q) * (pooled - n * q) / (n * q * (1.0 - q));
  }
  for (std::size_t i = 0; i + 1 < K; ++i) {
    double c = 0.0;
    for (const auto& hp : h) c += (hp[i] - mean[i]) * (hp[i + 1] - mean[i + 1]) / (pixels - 1);
    s.zCorrelation += c / (sd[i] * sd[i + 1]);
  }
  s.zCorrelation *= std::sqrt(static_cast<double>(pixels) / static_cast<double>(K - 1));
  return s;
}

// The engine's dead time of d bins covers the rest of the firing bin and d
// more, so a dead time one bin long in hardware (ending inside the next bin,
// live at the TDC's next clock) is d = 0: at most one count per bin and cycle.
TEST(SpadMultiStopTest, UnlimitedStopsAndAOneBinDeadTimeMakeIndependentBinomialBins) {
  const std::vector<double> flux = brightFlux();
  const int dof = static_cast<int>(flux.size());
  const BinStatistics s = independence(flux, 0, 0, 400, 2000);
  EXPECT_LT(s.chiSquare, tofsim::test::chiSquareQuantile(dof, 3.09));
  EXPECT_LT(std::fabs(s.zCorrelation), 4.0);
  // A bin more of dead time: each count blanks the next bin (anti-correlated
  // neighbours, fewer counts).
  const BinStatistics longer = independence(flux, 1, 0, 400, 2000);
  EXPECT_GT(longer.chiSquare, tofsim::test::chiSquareQuantile(dof, 3.09));
  EXPECT_LT(longer.zCorrelation, -8.0);
  // Two stops: the bins after the second are emptied (pile-up again).
  const BinStatistics twoStops = independence(flux, 0, 2, 400, 2000);
  EXPECT_GT(twoStops.chiSquare, tofsim::test::chiSquareQuantile(dof, 3.09));
}

// One stop: the first-photon law, also with a dead time that ends inside
// the cycle (the avalanches after the stop change nothing later). Flux in
// the first half of the cycle only, so 40 dead bins stay in it.
TEST(SpadMultiStopTest, OneStopIsTheFirstPhotonLaw) {
  std::vector<double> flux(120, 0.0);
  for (int t = 0; t < 60; ++t) flux[t] = 0.004 + 0.3 * std::exp(-0.05 * (t - 30) * (t - 30));
  const double n = 1e6;
  for (int32_t dead : {0, 40}) {
    SCOPED_TRACE("dead bins " + std::to_string(dead));
    const tofsim::test::ChiSquare chi =
        againstFirstPhoton(engine(flux, 1000000, dead, 1, 5), flux, n);
    EXPECT_LT(chi.statistic, tofsim::test::chiSquareQuantile(chi.dof, 3.09));
  }
  // A dead time that runs past the cycle's end loses the next cycles' early
  // bins after a late avalanche: no longer the first-photon law.
  const tofsim::test::ChiSquare past =
      againstFirstPhoton(engine(flux, 1000000, 100, 1, 5), flux, n);
  EXPECT_GT(past.statistic, tofsim::test::chiSquareQuantile(past.dof, 3.09));
}

// Flux in bin b only (q_b = P) and a dead time of m B - 1 bins after it: the
// detector is live again exactly at bin b of the m-th next cycle, so cycles
// between detections are (m - 1) + Geometric(P) (mean mu = m - 1 + 1 / P,
// variance (1 - P) / P^2): P / (1 + (m - 1) P) detections per cycle, with
// the renewal count's variance N sigma^2 / mu^3. Through the SPAD model
// (synchronous, one stop), which must pick the engine for it.
TEST(SpadMultiStopTest, ADeadTimeOfMCyclesGivesPOverOnePlusMMinusOneP) {
  const double w = 10e-12;
  const int32_t B = 50;
  TransientVolume v = test::makeVolume(1, 1, 0.0, w, B);
  const double flux = 0.7;
  v.at(0, 0, 20, 0) = static_cast<float>(flux);
  const double P = -std::expm1(-flux);
  SpadParams p;
  p.cycles = 1000000;
  p.pde = 1.0;
  for (int m : {2, 3}) {
    SCOPED_TRACE("m = " + std::to_string(m));
    p.dead_time_s = (m * B - 1) * w;
    const std::vector<SensorOutput> outs = runSpad(v, p, 7);
    const SensorOutput& c = test::array(outs, "spad_counts");
    double total = 0.0;
    for (float x : c.data) total += x;
    const double mu = m - 1 + 1.0 / P, var = (1.0 - P) / (P * P);
    const double expected = p.cycles * P / (1.0 + (m - 1) * P);
    const double sd = std::sqrt(p.cycles * var / (mu * mu * mu));
    EXPECT_NEAR(total, expected, 4.0 * sd);
    // One cycle more or less of dead time is a different rate.
    for (int other : {m - 1, m + 1}) {
      EXPECT_GT(std::fabs(total - p.cycles * P / (1.0 + (other - 1) * P)), 20.0 * sd) << other;
    }
  }
}

// The model routes to the engine exactly where the fast draws are not exact:
// unlimited stops with dead time 0 give binomial bins (chi-square), one stop
// with a dead time inside the cycle keeps the fast path's bytes.
TEST(SpadMultiStopTest, TheSpadModelUsesTheEngineWhereTheEffectNeedsIt) {
  const double w = 10e-12;
  const std::vector<double> flux = brightFlux();
  const auto K = static_cast<int32_t>(flux.size());
  TransientVolume v = test::makeVolume(8, 8, 0.0, w, K + 40);  // 40 dark bins after the light
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      for (int32_t t = 0; t < K; ++t) v.at(y, x, t, 0) = static_cast<float>(flux[t]);
  SpadParams p;
  p.cycles = 20000;
  p.pde = 1.0;
  p.tdc_stops = 0;
  const std::vector<SensorOutput> outs = runSpad(v, p, 3);
  const SensorOutput& c = test::array(outs, "spad_counts");
  const std::size_t bins = static_cast<std::size_t>(K) + 40;
  double chi = 0.0;
  for (int32_t t = 0; t < K; ++t) {
    double pooled = 0.0;
    for (std::size_t i = t; i < c.data.size(); i += bins) pooled += c.data[i];
    const double n = 64.0 * p.cycles, q = -std::expm1(-flux[t]);
    chi += (pooled - n * q) * (pooled - n * q) / (n * q * (1.0 - q));
  }
  EXPECT_LT(chi, tofsim::test::chiSquareQuantile(K, 3.09));
  p.tdc_stops = 1;  // the first-photon law instead: rejected
  const std::vector<SensorOutput> firstOuts = runSpad(v, p, 3);
  const SensorOutput& first = test::array(firstOuts, "spad_counts");
  double firstChi = 0.0;
  for (int32_t t = 0; t < K; ++t) {
    double pooled = 0.0;
    for (std::size_t i = t; i < first.data.size(); i += bins) pooled += first.data[i];
    const double n = 64.0 * p.cycles, q = -std::expm1(-flux[t]);
    firstChi += (pooled - n * q) * (pooled - n * q) / (n * q * (1.0 - q));
  }
  EXPECT_GT(firstChi, tofsim::test::chiSquareQuantile(K, 3.09));
  // Dead time ending in the dark part of the cycle: the first-photon fast
  // path, the same bytes as without dead time.
  p.dead_time_s = 30 * w;
  const std::vector<SensorOutput> deadOuts = runSpad(v, p, 3);
  EXPECT_EQ(test::array(deadOuts, "spad_counts").data, first.data);
}

}  // namespace
}  // namespace tofsim::sensors
