// The SPAD array's fixed pattern (fpn_seed, pde_spread, dark_count_log_sigma,
// hot and dead pixels): a property of the device, not of the noise.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "TestVolumes.h"
#include "support/ChiSquare.h"
#include "support/ShortNumber.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/sensors/SpadPixelMaps.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {
namespace {

using tofsim::test::sci;

using test::array;
using test::makeVolume;
using test::output;

constexpr int32_t kSide = 128, kBins = 32;
constexpr double kW = 100e-12;

SpadParams device() {
  SpadParams p;
  p.cycles = 1000;
  p.pde = 0.3;
  p.ambient_rate_per_s = 2e7;
  p.dark_count_rate_per_s = 1e6;  // median
  p.fpn_seed = 11;
  p.pde_spread = 0.1;
  p.dark_count_log_sigma = 0.8;
  p.hot_pixel_fraction = 0.02;
  p.hot_pixel_rate_per_s = 5e8;
  p.dead_pixel_fraction = 0.01;
  return p;
}

TransientVolume lit(int32_t side) {
  TransientVolume v = makeVolume(side, side, 0.0, kW, kBins);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) v.at(y, x, 10, 0) = 0.5f;
  return v;
}

TEST(SpadPixelMapsTest, SameUnderEveryNoiseSeedAndNewForAnotherFpnSeed) {
  const TransientVolume v = lit(16);
  const SpadParams p = device();
  const auto a = runSpad(v, p, 1), b = runSpad(v, p, 2);
  for (const char* name : {"spad_pde_map", "spad_dcr_map"}) {
    EXPECT_EQ(output(a, name).data, output(b, name).data) << name;
  }
  EXPECT_NE(array(a, "spad_counts").data, array(b, "spad_counts").data);
  SpadParams other = p;
  other.fpn_seed = 12;
  const auto c = runSpad(v, other, 1);
  for (const char* name : {"spad_pde_map", "spad_dcr_map"}) {
    EXPECT_NE(output(a, name).data, output(c, name).data) << name;
  }
  // Without any pattern parameter there are no maps, and every pixel is alike.
  SpadParams uniform;
  uniform.fpn_seed = 11;
  EXPECT_EQ(findOutput(runSpad(v, uniform, 1), "spad_pde_map", SensorOutput::Kind::Image), nullptr);
}

TEST(SpadPixelMapsTest, DeadPixelsCountNothing) {
  const TransientVolume v = lit(kSide / 2);
  const SpadParams p = device();
  const auto outs = runSpad(v, p, 3);
  const SensorOutput& counts = array(outs, "spad_counts");
  const SpadPixelMaps maps = spadPixelMaps(p, kSide / 2, kSide / 2);
  ASSERT_GT(maps.dead, 0);
  int64_t dead = 0;
  for (std::size_t px = 0; px < maps.kind.size(); ++px) {
    double total = 0.0;
    for (int t = 0; t < kBins; ++t) total += counts.data[px * kBins + t];
    if (maps.kind[px] == SpadPixelClass::Dead) {
      EXPECT_EQ(total, 0.0) << "dead pixel " << px;
      ++dead;
    } else {
      EXPECT_GT(total, 0.0) << "live pixel " << px;  // bright: a live pixel always counts
    }
  }
  EXPECT_EQ(dead, maps.dead);
  const SensorOutput& dcr = output(outs, "spad_dcr_map");
  ASSERT_EQ(dcr.attributes.size(), 2u);
  EXPECT_EQ(dcr.attributes[0].first, "hot_pixels");
  EXPECT_EQ(dcr.attributes[0].second, static_cast<double>(maps.hot));
  EXPECT_EQ(dcr.attributes[1].second, static_cast<double>(maps.dead));
}

// Kolmogorov-Smirnov statistic of ln(dcr / median) / sigma against N(0, 1).
double ksAgainstLogNormal(std::vector<double> dcr, double median, double sigma) {
  std::vector<double> z;
  for (double r : dcr) z.push_back(std::log(r / median) / sigma);
  std::sort(z.begin(), z.end());
  const double n = static_cast<double>(z.size());
  double d = 0.0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    const double F = 0.5 * std::erfc(-z[i] / std::sqrt(2.0));
    d = std::max({d, F - i / n, (i + 1) / n - F});
  }
  return d;
}

TEST(SpadPixelMapsTest, DarkCountMapIsLogNormalWithItsHotAndDeadFractions) {
  const SpadParams p = device();
  const SpadPixelMaps maps = spadPixelMaps(p, kSide, kSide);
  const double n = double(kSide) * kSide;
  std::vector<double> normal;
  double pdeSum = 0.0;
  for (std::size_t px = 0; px < maps.kind.size(); ++px) {
    if (maps.kind[px] == SpadPixelClass::Normal) normal.push_back(maps.dcr_per_s[px]);
    if (maps.kind[px] == SpadPixelClass::Hot) {
      EXPECT_EQ(maps.dcr_per_s[px], p.hot_pixel_rate_per_s);
    }
    if (maps.kind[px] != SpadPixelClass::Dead) pdeSum += maps.pde[px];
  }
  // p > 0.01: D < 1.628 / sqrt(n); the same map against sigma x 1.1 (or a
  // median 10 % off) is rejected.
  const double critical = 1.628 / std::sqrt(static_cast<double>(normal.size()));
  const double d = ksAgainstLogNormal(normal, p.dark_count_rate_per_s, p.dark_count_log_sigma);
  RecordProperty("ks_d", sci(d));
  RecordProperty("ks_critical", sci(critical));
  EXPECT_LT(d, critical);
  EXPECT_GT(ksAgainstLogNormal(normal, p.dark_count_rate_per_s, 1.1 * p.dark_count_log_sigma),
            critical);
  EXPECT_GT(ksAgainstLogNormal(normal, 1.1 * p.dark_count_rate_per_s, p.dark_count_log_sigma),
            critical);
  // Fractions within 4 binomial sigmas.
  const double live = n - static_cast<double>(maps.dead);
  EXPECT_NEAR(maps.dead, n * p.dead_pixel_fraction,
              4.0 * std::sqrt(n * p.dead_pixel_fraction * (1 - p.dead_pixel_fraction)));
  EXPECT_NEAR(maps.hot, live * p.hot_pixel_fraction,
              4.0 * std::sqrt(live * p.hot_pixel_fraction * (1 - p.hot_pixel_fraction)));
  // Mean PDE of live pixels within 3 sigma / sqrt(n).
  const double sd = p.pde * p.pde_spread;
  EXPECT_NEAR(pdeSum / live, p.pde, 3.0 * sd / std::sqrt(live));
}

TEST(SpadPixelMapsTest, SameBytesForAnyThreadCount) {
  const TransientVolume v = lit(24);
  const SpadParams p = device();
  std::vector<float> first;
  for (int threads : {1, 2, 5}) {
    StreamOptions options;
    options.seed = 9;
    options.threads = threads;
    auto stream = openSpad(p, shapeOf(v), options);
    stream->consume(wholeVolume(v));
    const auto outs = stream->finish(nullptr);
    std::vector<float> bytes = array(outs, "spad_counts").data;
    const auto& dcr = output(outs, "spad_dcr_map").data;
    bytes.insert(bytes.end(), dcr.begin(), dcr.end());
    if (first.empty()) first = bytes;
    EXPECT_EQ(bytes, first) << threads << " threads";
  }
}

// A measured map replaces the log-normal draw: live pixels take its rate,
// hot and dead pixels still apply, and the dark counts follow it.
TEST(SpadPixelMapsTest, MeasuredDarkCountMapReplacesTheLogNormal) {
  constexpr int32_t side = 16;
  SpadParams p = device();
  p.dark_count_log_sigma = 0.0;
  p.ambient_rate_per_s = 0.0;
  p.cycles = 20000;
  p.dark_count_map.file = "measured.npy";
  p.dark_count_map.height = p.dark_count_map.width = side;
  for (int px = 0; px < side * side; ++px) {
    p.dark_count_map.rates_per_s.push_back(px % 7 == 0 ? 5e8 : 1e6 * (1 + px % 5));
  }
  const TransientVolume v = makeVolume(side, side, 0.0, kW, kBins);
  const auto outs = runSpad(v, p, 4);
  const SpadPixelMaps maps = spadPixelMaps(p, side, side);
  const std::vector<float>& dcr = output(outs, "spad_dcr_map").data;
  const SensorOutput& counts = array(outs, "spad_counts");
  double chi = 0.0;
  int normal = 0;
  for (std::size_t px = 0; px < dcr.size(); ++px) {
    const double measured = p.dark_count_map.rates_per_s[px];
    if (maps.kind[px] == SpadPixelClass::Dead) {
      EXPECT_EQ(dcr[px], 0.0f);
      continue;
    }
    if (maps.kind[px] == SpadPixelClass::Hot) {
      EXPECT_EQ(dcr[px], static_cast<float>(p.hot_pixel_rate_per_s));
      continue;
    }
    EXPECT_EQ(dcr[px], static_cast<float>(measured)) << px;
    // Its dark counts: Binomial(N, 1 - exp(-rate x window)) detecting cycles.
    double total = 0.0;
    for (int t = 0; t < kBins; ++t) total += counts.data[px * kBins + t];
    const double P = -std::expm1(-measured * kBins * kW), mean = p.cycles * P;
    chi += (total - mean) * (total - mean) / (mean * (1.0 - P));
    ++normal;
  }
  RecordProperty("chi2", sci(chi));
  EXPECT_LT(chi, tofsim::test::chiSquareQuantile(normal, 3.09));
  // A map of another shape is an InputError at the stream.
  EXPECT_THROW(runSpad(makeVolume(side, side + 1, 0.0, kW, kBins), p, 4), InputError);
}

}  // namespace
}  // namespace tofsim::sensors
