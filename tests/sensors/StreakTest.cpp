#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "TestVolumes.h"
#include "tofsim/sensors/Streak.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {
namespace {

using test::makeVolume;
using test::output;

StreakParams noiseFree() {
  StreakParams p;
  p.shot_noise = false;
  p.read_noise_e = 0.0;
  p.saturation_adu = 1e30;
  return p;
}

TEST(StreakTest, DeltaBecomesThePsfAtTheRightPlace) {
  const double w = 2e-12;
  TransientVolume v = makeVolume(32, 4, 0.0, w, 200);
  const int32_t x0 = 13, t0 = 90;
  const double energy = 1000.0;
  v.at(2, x0, t0, 0) = static_cast<float>(energy);
  StreakParams p = noiseFree();
  p.rows = {2};
  p.time_fwhm_s = 30e-12;
  p.spatial_fwhm_px = 3.0;
  const auto outs = runStreak(v, p, 1);
  ASSERT_EQ(outs.size(), 2u);
  const SensorOutput& img = output(outs, "streak_row002");
  ASSERT_EQ(img.shape, (std::vector<int64_t>{200, 32}));
  EXPECT_NE(findOutput(outs, "streak_row002", SensorOutput::Kind::ColorMappedImage), nullptr);

  // Moments of the image against the Gaussian PSF: centred on the delta's bin,
  // variance sigma^2 plus 1/6 bin^2 (uniform source in its bin, binned detection).
  const double st = 30e-12 / 2.3548200450309493 / w, sx = 3.0 / 2.3548200450309493;
  double sum = 0, mt = 0, mx = 0, vt = 0, vx = 0;
  for (int t = 0; t < 200; ++t) {
    for (int x = 0; x < 32; ++x) {
      const double e = img.data[t * 32 + x];
      sum += e;
      mt += e * t;
      mx += e * x;
    }
  }
  mt /= sum;
  mx /= sum;
  for (int t = 0; t < 200; ++t) {
    for (int x = 0; x < 32; ++x) {
      const double e = img.data[t * 32 + x];
      vt += e * (t - mt) * (t - mt) / sum;
      vx += e * (x - mx) * (x - mx) / sum;
    }
  }
  EXPECT_NEAR(sum, energy, 1e-3);
  EXPECT_NEAR(mt, t0, 1e-3);
  EXPECT_NEAR(mx, x0, 1e-3);
  EXPECT_NEAR(vt, st * st + 1.0 / 6.0, 0.01 * st * st);
  EXPECT_NEAR(vx, sx * sx + 1.0 / 6.0, 0.01 * sx * sx);
  // Peak and neighbours: energy times the Gaussian averaged over source and
  // target bin, K(d) = g(d + 1) - 2 g(d) + g(d - 1), g(x) = x Phi(x/s) + s phi(x/s).
  auto k = [](double d, double s) {
    auto g = [s](double x) {
      return x * 0.5 * std::erfc(-x / s / std::sqrt(2.0)) +
             s * std::exp(-0.5 * x * x / (s * s)) / std::sqrt(2.0 * M_PI);
    };
    return g(d + 1) - 2 * g(d) + g(d - 1);
  };
  for (int dt : {0, 3}) {
    for (int dx : {0, -2}) {
      const double expected = energy * k(dt, st) * k(dx, sx);
      EXPECT_NEAR(img.data[(t0 + dt) * 32 + x0 + dx], expected, 0.002 * expected) << dt << dx;
    }
  }
  // Other rows are not recorded; a blank row would be all zero.
  EXPECT_EQ(findOutput(outs, "streak_row001", SensorOutput::Kind::Image), nullptr);
}

TEST(StreakTest, BlurConservesTotalSignalIncludingEdges) {
  TransientVolume v = makeVolume(16, 2, 1e-9, 5e-12, 64);
  for (std::size_t i = 0; i < v.size(); ++i) v.values()[i] = static_cast<float>((i * 7919) % 13);
  StreakParams p = noiseFree();
  p.time_fwhm_s = 80e-12;
  p.spatial_fwhm_px = 5.0;
  p.bins.offset_s = 1e-9;  // the render's own bins
  const auto outs = runStreak(v, p, 1);
  for (int32_t row = 0; row < 2; ++row) {
    double in = 0.0;
    for (int x = 0; x < 16; ++x) {
      for (int t = 0; t < 64; ++t) in += v.at(row, x, t, 0);
    }
    const SensorOutput& img = output(outs, streakRowName(row));
    const double out = std::accumulate(img.data.begin(), img.data.end(), 0.0);
    EXPECT_NEAR(out, in, 1e-5 * in) << "row " << row;
  }
}

TEST(StreakTest, ShotNoiseVarianceEqualsMeanAndReadNoiseAdds) {
  const double mu = 50.0;
  TransientVolume v = makeVolume(64, 1, 0.0, 1e-12, 200);
  for (float& f : v.values()) f = static_cast<float>(mu);
  StreakParams p;
  p.saturation_adu = 1e9;
  const int n = 64 * 200;
  for (double readNoise : {0.0, 5.0}) {
    p.read_noise_e = readNoise;
    const auto outs = runStreak(v, p, 11);
    const SensorOutput& img = output(outs, "streak_row000");
    double s = 0, s2 = 0;
    for (float e : img.data) {
      s += e;
      s2 += static_cast<double>(e) * e;
    }
    const double mean = s / n, var = (s2 - s * s / n) / (n - 1);
    const double expectVar = mu + readNoise * readNoise;
    EXPECT_NEAR(mean, mu, 4.0 * std::sqrt(expectVar / n));
    // Var of the sample variance ~ (mu4 - sigma^4) / n; mu4 ~ 3 sigma^4 + mu.
    EXPECT_NEAR(var, expectVar, 4.0 * std::sqrt((2.0 * expectVar * expectVar + mu) / n));
  }
}

TEST(StreakTest, GainSaturationAndReproducibility) {
  TransientVolume v = makeVolume(8, 2, 0.0, 1e-12, 50);
  for (float& f : v.values()) f = 30.0f;
  StreakParams p;
  p.gain_adu_per_e = 4.0;
  p.saturation_adu = 130.0;
  p.read_noise_e = 1.0;
  const auto a = runStreak(v, p, 5), b = runStreak(v, p, 5), c = runStreak(v, p, 6);
  const SensorOutput& img = output(a, "streak_row001");
  int saturated = 0;
  for (float e : img.data) {
    EXPECT_LE(e, 130.0f);
    EXPECT_GE(e, 0.0f);
    saturated += e == 130.0f;
  }
  EXPECT_GT(saturated, 100);  // mean 120 ADU, sd ~ 22 ADU: a third clip
  EXPECT_EQ(output(a, "streak_row001").data, output(b, "streak_row001").data);
  EXPECT_NE(output(a, "streak_row001").data, output(c, "streak_row001").data);
}

TEST(StreakTest, RowOutsideTheImageIsAnInputError) {
  TransientVolume v = makeVolume(4, 4, 0.0, 1e-12, 8);
  StreakParams p;
  p.rows = {4};
  EXPECT_THROW(runStreak(v, p, 1), InputError);
}

}  // namespace
}  // namespace tofsim::sensors
