// Crosstalk exact in the event engine (SpadArrayEvents.h, the array driver,
// and the model's `engine: exact` through it): a lit 3 x 3 array against the
// avalanche-by-avalanche oracle (CrosstalkOracle.h) at p = 0.05, where the
// first-order path fails; a dark neighbour's Multinomial(N, p P_A) law, also
// behind a ramped gate, and free-running Binomial(N, p q_i) per bin; without crosstalk the bytes of
// the one-pixel engine; the same bytes for any spans and thread counts.

#include <gtest/gtest.h>

#include <cstring>
#include <iostream>
#include <vector>

#include "CrosstalkOracle.h"
#include "SpadArrayEvents.h"
#include "SpadEventEngine.h"
#include "SpadGate.h"
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

constexpr double kW = 10e-12;  // TDC and render bin width
constexpr int32_t kSide = 3, kBins = 40;
constexpr int64_t kCycles = 200'000;

TransientVolume volumeOf(int32_t w, int32_t h, const std::vector<std::vector<double>>& flux) {
  const auto bins = static_cast<int32_t>(flux[0].size());
  TransientVolume v = makeVolume(w, h, 0.0, kW, bins);
  for (int32_t y = 0; y < h; ++y)
    for (int32_t x = 0; x < w; ++x)
      for (int32_t t = 0; t < bins; ++t)
        v.at(y, x, t, 0) = static_cast<float>(flux[static_cast<std::size_t>(y * w + x)][t]);
  return v;
}

std::vector<std::vector<double>> litArray() {
  std::vector<std::vector<double>> flux;
  for (int32_t y = 0; y < kSide; ++y)
    for (int32_t x = 0; x < kSide; ++x) flux.push_back(litPixel(y, x, kBins));
  return flux;
}

TwoSample twoSample(const std::vector<std::vector<double>>& a,
                    const std::vector<std::vector<double>>& b, double cycles) {
  TwoSample t;
  for (std::size_t k = 0; k < a.size(); ++k) addTwoSample(a[k], b[k], cycles, t);
  return t;
}

// The driver on its own pixel streams.
std::vector<std::vector<double>> drive(int32_t w, int32_t h,
                                       const std::vector<std::vector<double>>& flux,
                                       uint64_t cycles, const detail::DetectorLaws& laws,
                                       const detail::CrosstalkLaw& crosstalk, uint64_t seed) {
  std::vector<Rng> rngs;
  for (std::size_t px = 0; px < flux.size(); ++px) rngs.emplace_back(seed, px);
  std::vector<std::vector<double>> hist(flux.size(), std::vector<double>(flux[0].size(), 0.0));
  detail::spadArrayEvents(w, h, flux, {}, cycles, laws, crosstalk, rngs, hist);
  return hist;
}

// The driver against the oracle as it stands (dead for the rest of the cycle
// after the stop: a single-stop detector without everyAvalanche skips to the
// next pulse): p = 0.05, where first order's O(p^2) shows (the fast path's
// two-sample chi-square there: 902 on 360 dof, SpadCrosstalkTest). 4
// neighbours, p = 0.04 and no crosstalk are rejected.
TEST(SpadArrayEventsTest, DriverAgreesWithTheAvalancheOracleWhereFirstOrderFails) {
  const double p = 0.05;
  const std::vector<std::vector<double>> flux = litArray();
  const test::ArrayOracle oracle{kSide, kSide, kBins, true, p, flux};
  const std::vector<std::vector<double>> exact = oracle.run(kCycles, 21);
  detail::DetectorLaws laws;  // one stop, no dead time beyond the bin
  const auto compare = [&](double q, bool eight) {
    const detail::CrosstalkLaw crosstalk{q, eight, 0.0};
    return twoSample(drive(kSide, kSide, flux, kCycles, laws, crosstalk, 22), exact, kCycles);
  };
  const TwoSample same = compare(p, true);
  std::cout << "driver vs oracle, p " << p << ": chi2 " << same.statistic << " / " << same.dof
            << " dof\n";
  EXPECT_LT(same.statistic, chiSquareQuantile(same.dof, 3.09));
  const TwoSample lower = compare(0.04, true);
  std::cout << "p 0.04: chi2 " << lower.statistic << "\n";
  EXPECT_GT(lower.statistic, chiSquareQuantile(lower.dof, 3.09));
  EXPECT_GT(compare(p, false).statistic, chiSquareQuantile(same.dof, 3.09));
  EXPECT_GT(compare(0.0, true).statistic, chiSquareQuantile(same.dof, 3.09));
}

SpadParams exactCrosstalk(double p) {
  SpadParams s;
  s.cycles = kCycles;
  s.pde = 1.0;
  s.engine = SpadEngine::Exact;
  s.crosstalk_probability = p;
  s.crosstalk_neighbours = CrosstalkNeighbours::Eight;
  return s;
}

std::vector<std::vector<double>> perPixel(const std::vector<SensorOutput>& outs, int32_t bins) {
  const SensorOutput& c = array(outs, "spad_counts");
  std::vector<std::vector<double>> h(c.data.size() / bins);
  for (std::size_t k = 0; k < h.size(); ++k)
    h[k].assign(c.data.begin() + k * bins, c.data.begin() + (k + 1) * bins);
  return h;
}

// The model's engine keeps a detector running after its stop (its later
// avalanches are not counted but send crosstalk): `engine: exact` agrees
// with the oracle that recharges, and is rejected by the one that stays dead
// after the stop (the difference is O(p), not O(p^2)).
TEST(SpadArrayEventsTest, ExactEngineAgreesWithTheRechargingOracle) {
  const double p = 0.05;
  const std::vector<std::vector<double>> flux = litArray();
  const std::vector<std::vector<double>> model =
      perPixel(runSpad(volumeOf(kSide, kSide, flux), exactCrosstalk(p), 23), kBins);
  test::ArrayOracle oracle{kSide, kSide, kBins, true, p, flux};
  oracle.recharges = true;
  const TwoSample same = twoSample(model, oracle.run(kCycles, 24), kCycles);
  std::cout << "engine: exact vs recharging oracle, p " << p << ": chi2 " << same.statistic << " / "
            << same.dof << " dof\n";
  EXPECT_LT(same.statistic, chiSquareQuantile(same.dof, 3.09));
  oracle.recharges = false;
  const TwoSample disarmed = twoSample(model, oracle.run(kCycles, 24), kCycles);
  std::cout << "vs the oracle dead after its stop: chi2 " << disarmed.statistic << "\n";
  EXPECT_GT(disarmed.statistic, chiSquareQuantile(disarmed.dof, 3.09));
}

// A's light: a broad return over bins 10-39 of 80 (P_det 0.72).
constexpr int32_t kStripBins = 80;
std::vector<double> brightReturn() {
  std::vector<double> f(kStripBins, 0.0);
  for (int32_t t = 10; t < 40; ++t) f[t] = static_cast<float>(0.045 * (1.0 + std::sin(0.2 * t)));
  return f;
}

// A strip B A B (4 neighbours: each B's only neighbour is A), B dark, a dead
// time of 40 bins: A fires once per cycle (live again after its light), in
// bin i with probability P_A,i; B's arrivals back at A come while A is dead.
// So each B counts Multinomial(N, p g_i P_A,i) exactly, g the gate's bin
// average (1 without a gate), for any p: no chains to leave out.
std::vector<double> stripB(const SpadParams& s, uint64_t seed) {
  const std::vector<double> dark(kStripBins, 0.0);
  const std::vector<std::vector<double>> h =
      perPixel(runSpad(volumeOf(3, 1, {dark, brightReturn(), dark}), s, seed), kStripBins);
  std::vector<double> b(kStripBins);
  for (int32_t t = 0; t < kStripBins; ++t) b[t] = h[0][t] + h[2][t];
  return b;
}

std::vector<double> times(const std::vector<double>& a, const std::vector<double>& b, double s) {
  std::vector<double> v(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) v[i] = s * a[i] * b[i];
  return v;
}

SpadParams strip(double p) {
  SpadParams s = exactCrosstalk(p);
  s.cycles = 1'000'000;
  s.crosstalk_neighbours = CrosstalkNeighbours::Four;
  s.dead_time_s = 40 * kW;
  return s;
}

TEST(SpadArrayEventsTest, DarkNeighbourCountsTheBrightPixelsStopsThinnedByP) {
  const double p = 0.2;
  const SpadParams s = strip(p);
  const std::vector<double> hB = stripB(s, 25);
  const std::vector<double> ones(kStripBins, 1.0), PA = firstPhotonProbabilities(brightReturn());
  const double draws = 2.0 * static_cast<double>(s.cycles);
  const auto fit = againstMultinomial(hB, times(PA, ones, p), draws);
  std::cout << "dark neighbour, p " << p << ": chi2 " << fit.statistic << " / " << fit.dof
            << " dof\n";
  EXPECT_LT(fit.statistic, chiSquareQuantile(fit.dof, 3.09));
  const auto off = againstMultinomial(hB, times(PA, ones, 1.05 * p), draws);
  EXPECT_GT(off.statistic, chiSquareQuantile(off.dof, 3.09));
  const auto none = againstMultinomial(stripB(strip(0.0), 25), times(PA, ones, p), draws);
  EXPECT_GT(none.statistic, chiSquareQuantile(none.dof, 3.09));
}

// Behind a ramped gate (modelled by the driver only; `engine: auto` picks
// it): A's law is the first-photon law of its gated flux, and B takes an
// arrival in bin i with its own gate's bin average g_i. Taking every arrival
// (a receiver without its gate) is rejected.
TEST(SpadArrayEventsTest, DarkNeighbourBehindARampedGate) {
  const double p = 0.2;
  SpadParams s = strip(p);
  s.engine = SpadEngine::Auto;
  s.gate_start_s = 20 * kW;
  s.gate_width_s = 14 * kW;
  s.gate_rise_s = 10 * kW;
  s.gate_fall_s = 6 * kW;
  const std::vector<double> hB = stripB(s, 26);
  std::vector<double> g(kStripBins, 1.0), gated = brightReturn();
  const detail::TdcBins bins = detail::tdcBins(s, TimeAxis{0.0, kW, kStripBins});
  detail::applyGate(detail::spadGate(s), bins, g);
  detail::applyGate(detail::spadGate(s), bins, gated);
  const std::vector<double> PA = firstPhotonProbabilities(gated);
  const double draws = 2.0 * static_cast<double>(s.cycles);
  const auto fit = againstMultinomial(hB, times(PA, g, p), draws);
  std::cout << "ramped gate: chi2 " << fit.statistic << " / " << fit.dof << " dof\n";
  EXPECT_LT(fit.statistic, chiSquareQuantile(fit.dof, 3.09));
  const std::vector<double> ones(kStripBins, 1.0);
  const auto ungated = againstMultinomial(hB, times(PA, ones, p), draws);
  EXPECT_GT(ungated.statistic, chiSquareQuantile(ungated.dof, 3.09));
}

// Free-running, no dead time beyond the bin: A fires in bin i of a period
// with probability q_i = 1 - e^(-f_i), the bins independent, and B (left of
// A in the strip) then with probability p, so its bins are independent
// Binomial(N, p q_i); nothing where A has no light. p 5 % higher is rejected.
TEST(SpadArrayEventsTest, FreeRunningDarkNeighbourIsBinomialPerBin) {
  const double p = 0.2;
  SpadParams s = strip(p);
  s.mode = SpadMode::FreeRunning;
  s.dead_time_s = 0.0;
  const std::vector<double> dark(kStripBins, 0.0), a = brightReturn();
  const std::vector<double> hB =
      perPixel(runSpad(volumeOf(3, 1, {dark, a, dark}), s, 28), kStripBins)[0];
  const auto n = static_cast<double>(s.cycles);
  const auto chiSquare = [&](double q) {
    double x2 = 0.0;
    for (int32_t i = 0; i < kStripBins; ++i) {
      const double pi = q * -std::expm1(-a[i]);
      if (pi == 0.0) {
        EXPECT_EQ(hB[i], 0.0) << i;
        continue;
      }
      x2 += (hB[i] - n * pi) * (hB[i] - n * pi) / (n * pi * (1.0 - pi));
    }
    return x2;
  };
  const int dof = 30;  // A's lit bins
  const double x2 = chiSquare(p);
  std::cout << "free-running dark neighbour: chi2 " << x2 << " / " << dof << " dof\n";
  EXPECT_LT(x2, chiSquareQuantile(dof, 3.09));
  EXPECT_GT(chiSquare(1.05 * p), chiSquareQuantile(dof, 3.09));
}

// No crosstalk: every pixel's bytes are the one-pixel engine's on its stream
// (multi-stop, dead time past the cycle, afterpulses); with crosstalk they
// are not.
TEST(SpadArrayEventsTest, WithoutCrosstalkEachPixelIsTheOnePixelEngine) {
  constexpr int32_t w = 4, h = 3;
  std::vector<std::vector<double>> flux;
  for (int32_t k = 0; k < w * h; ++k) {
    std::vector<double> f(kBins, 0.003 * (k % 3));
    for (int32_t t = 5 + 2 * k; t < 12 + 2 * k; ++t) f[t] += 0.04 * (1 + k % 4);
    flux.push_back(f);
  }
  detail::DetectorLaws laws;
  laws.stops = 2;
  laws.deadBins = 30;
  laws.afterpulses.mean = 0.2;
  laws.afterpulses.delays_bins = {5.0, 60.0};
  laws.afterpulses.weights = {1.0, 1.0};
  const uint64_t cycles = 20'000;
  const auto array = drive(w, h, flux, cycles, laws, {0.0, true, 0.0}, 27);
  for (std::size_t px = 0; px < flux.size(); ++px) {
    Rng rng(27, px);
    std::vector<double> one(kBins, 0.0);
    detail::spadEvents(flux[px], cycles, laws, rng, one);
    EXPECT_EQ(array[px], one) << px;
  }
  EXPECT_NE(drive(w, h, flux, cycles, laws, {0.05, true, 0.0}, 27), array);
}

// One coupled region on one thread, each draw from its pixel's stream: the
// same bytes for spans of 1 to all pixels and 1 or 2 threads, both modes,
// delayed crosstalk with afterpulses and a skewed, ramped gate.
TEST(SpadArrayEventsTest, BytesDoNotDependOnSpansOrThreads) {
  constexpr int32_t w = 20, h = 10, bins = 32;
  std::vector<std::vector<double>> flux;
  for (int32_t y = 0; y < h; ++y) {
    for (int32_t x = 0; x < w; ++x) {
      std::vector<double> f(bins, 0.001);
      f[(x * 7 + y * 3) % bins] += 0.05 * (1 + (x * y) % 7);
      flux.push_back(f);
    }
  }
  const TransientVolume volume = volumeOf(w, h, flux);
  for (const SpadMode mode : {SpadMode::Synchronous, SpadMode::FreeRunning}) {
    SpadParams s = exactCrosstalk(0.05);
    s.cycles = 3000;
    s.mode = mode;
    s.crosstalk_delay_s = 25e-12;
    s.dead_time_s = 3 * kW;
    s.afterpulse_probability = 0.1;
    s.gate_start_s = 4 * kW;
    s.gate_width_s = 20 * kW;
    s.gate_rise_s = 2 * kW;
    s.gate_skew_sigma_s = 1 * kW;
    const std::vector<float> whole = array(runSpad(volume, s, 3), "spad_counts").data;
    SpadParams off = s;
    off.crosstalk_probability = 0.0;
    EXPECT_NE(whole, array(runSpad(volume, off, 3), "spad_counts").data);
    for (const int threads : {1, 2}) {
      for (const std::size_t span : {std::size_t{1}, std::size_t{13}, std::size_t{200}}) {
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
