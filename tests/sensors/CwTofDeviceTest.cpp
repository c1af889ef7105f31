// The CW-ToF device stage (CwTofDevice.h): raw moments against the gain x
// (signal + ambient + dark) and Poisson + read law, the fixed-pattern delay
// as an exact later arrival, gains and offsets that cancel in the DFT, the
// two-tap phasor bias, the ADC's codes, full well and saturation, ambient
// suppression, the fixed pattern's own seed, the capture's time stamps, and
// every default keeping today's bytes.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <cstring>
#include <map>
#include <vector>

#include "CwTofCorrelator.h"
#include "TestVolumes.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/sensors/CwTofDevice.h"
#include "tofsim/sensors/Random.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {
namespace {

using test::array;
using test::makeVolume;
using test::output;

/// A W x H volume, every pixel one return of `energy` in bin `bin` (and a
/// weaker second in bin 3 bin / 2), 20 ps bins from 0.
TransientVolume uniform(int32_t W, int32_t H, float energy, int32_t bin = 80, int32_t bins = 200) {
  TransientVolume v = makeVolume(W, H, 0.0, 20e-12, bins);
  for (int32_t y = 0; y < H; ++y) {
    for (int32_t x = 0; x < W; ++x) {
      v.at(y, x, bin, 0) = energy;
      v.at(y, x, 3 * bin / 2, 0) = 0.3f * energy;
    }
  }
  return v;
}

/// A volume whose pixels differ: a return of its own bin and energy each.
TransientVolume varied(int32_t W, int32_t H) {
  TransientVolume v = makeVolume(W, H, 0.0, 20e-12, 200);
  for (int32_t y = 0; y < H; ++y) {
    for (int32_t x = 0; x < W; ++x) {
      v.at(y, x, 20 + (7 * x + 13 * y) % 150, 0) = 50.0f + 40.0f * ((3 * x + y) % 9);
      v.at(y, x, 190 - (x + y) % 30, 0) = 10.0f;
    }
  }
  return v;
}

CwTofParams noiseFree() {
  CwTofParams p;
  p.shot_noise = false;
  return p;
}

CwTofPixelMap constantMap(int32_t W, int32_t H, double value) {
  return {"constant.npy", H, W, std::vector<double>(static_cast<std::size_t>(W) * H, value)};
}

/// sum over raws of (x - mean)^2 / variance: chi-square with n = raws.size()
/// degrees of freedom when mean and variance are the raws' law.
double chiSquare(const std::vector<float>& raws, const std::vector<float>& ideal, double gain,
                 double dark, double read) {
  double x2 = 0.0;
  for (std::size_t i = 0; i < raws.size(); ++i) {
    const double mean = gain * ideal[i] + dark, variance = mean + read * read;
    x2 += (raws[i] - mean) * (raws[i] - mean) / variance;
  }
  return x2;
}

TEST(CwTofDeviceTest, EveryDefaultKeepsTodaysBytes) {
  const TransientVolume v = varied(9, 7);
  CwTofParams today;
  today.frequencies_Hz = {20e6, 50e6};
  today.ambient_e = 40.0;
  today.read_noise_e = 3.0;
  const auto before = runCwTof(v, today, 11);
  // Today's noise stage, as it was written before the device stage: per
  // pixel its own stream, Poisson then read noise on each ideal raw.
  const Correlator correlator(today, v.axis());
  std::vector<double> signal, ideal;
  const std::vector<float>& raw = array(before, "cwtof_raw").data;
  const std::size_t HW = 63;
  for (std::size_t px = 0; px < HW; ++px) {
    pixelSignal(v, today.common, static_cast<int32_t>(px / 9), static_cast<int32_t>(px % 9),
                signal);
    correlator.raw(signal, today.ambient_e, ideal);
    Rng rng(11, pixelStream(0x4357, px));
    for (std::size_t j = 0; j < ideal.size(); ++j) {
      double x = static_cast<double>(rng.poisson(std::max(0.0, ideal[j])));
      x += rng.normal(0.0, today.read_noise_e);
      ASSERT_EQ(raw[j * HW + px], float(x)) << px << " " << j;
    }
  }
  // The device keys at their defaults, or set where they change nothing
  // (a pattern seed without a pattern, the capture's timing): the same bytes.
  CwTofParams keyed = today;
  keyed.fpn_seed = 99;
  keyed.taps = 1;
  keyed.capture_order = cwtofCaptureOrder(today);
  keyed.integration_time_s = 1e-3;
  keyed.readout_gap_s = 2e-4;
  EXPECT_FALSE(cwtofDeviceActive(keyed));
  const auto after = runCwTof(v, keyed, 11);
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(after[i].name, before[i].name);
    EXPECT_EQ(0, std::memcmp(after[i].data.data(), before[i].data.data(),
                             before[i].data.size() * sizeof(float)))
        << before[i].name;
  }
}

TEST(CwTofDeviceTest, RawMomentsFollowGainDarkPoissonAndRead) {
  const int32_t W = 48, H = 48;
  const TransientVolume v = uniform(W, H, 300.0f);
  CwTofParams p = noiseFree();
  p.ambient_e = 20.0;
  const std::vector<float> ideal = array(runCwTof(v, p, 1), "cwtof_raw").data;
  p.shot_noise = true;
  p.tap_a_gain = 1.7;
  p.dark_current_e = 20.0;
  p.read_noise_e = 20.0;
  p.adc_bits = 16;
  p.adc_gain_dn_per_e = 0.5;
  p.adc_offset_dn = 1000.0;
  const auto outs = runCwTof(v, p, 5);
  const std::vector<float>& raw = array(outs, "cwtof_raw").data;
  const double n = static_cast<double>(raw.size()), sd = std::sqrt(2.0 * n);
  const double x2 = chiSquare(raw, ideal, 1.7, 20.0, 20.0);
  std::printf(
      "chi-square %.0f on %.0f dof (sd %.0f); gain 1.6: %.0f; read 17: %.0f; dark 0: %.0f\n", x2, n,
      sd, chiSquare(raw, ideal, 1.6, 20.0, 20.0), chiSquare(raw, ideal, 1.7, 20.0, 17.0),
      chiSquare(raw, ideal, 1.7, 0.0, 20.0));
  EXPECT_LT(std::fabs(x2 - n), 4.0 * sd);
  // A wrong gain, read noise or dark current is rejected.
  EXPECT_GT(std::fabs(chiSquare(raw, ideal, 1.6, 20.0, 20.0) - n), 4.0 * sd);
  EXPECT_GT(std::fabs(chiSquare(raw, ideal, 1.7, 20.0, 17.0) - n), 4.0 * sd);
  EXPECT_GT(std::fabs(chiSquare(raw, ideal, 1.7, 0.0, 20.0) - n), 4.0 * sd);
  // The DN: G x + offset, rounded: variance G^2 (mean + read^2) + 1/12.
  const std::vector<float>& dn = array(outs, "cwtof_raw_dn").data;
  double dnX2 = 0.0;
  for (std::size_t i = 0; i < dn.size(); ++i) {
    const double mean = 1.7 * ideal[i] + 20.0;
    const double m = 0.5 * mean + 1000.0, var = 0.25 * (mean + 400.0) + 1.0 / 12.0;
    dnX2 += (dn[i] - m) * (dn[i] - m) / var;
  }
  std::printf("DN chi-square %.0f on %.0f dof\n", dnX2, n);
  EXPECT_LT(std::fabs(dnX2 - n), 4.0 * sd);
}

TEST(CwTofDeviceTest, DelayIsALaterArrivalExactly) {
  TimeAxis axis;
  axis.bin_width_s = 20e-12;
  axis.bins = 300;
  std::vector<double> signal(300, 0.0), later(300, 0.0);
  for (int32_t t : {40, 41, 90, 200}) signal[t] = 10.0 + t;
  const int32_t m = 17;  // the delay: m bins
  for (int32_t t = 0; t + m < 300; ++t) later[t + m] = signal[t];
  const double delta = m * axis.bin_width_s, k = axis.depthPerSecond_m_per_s();
  for (Waveform w : {Waveform::Sine, Waveform::Square, Waveform::Measured}) {
    for (int32_t N : {3, 4, 5}) {
      CwTofParams p;
      p.frequencies_Hz = {20e6, 70e6};
      p.phase_steps = N;
      p.waveform = w;
      if (w == Waveform::Measured) {
        CorrelationWaveform c;
        c.harmonics = {{1.0, 0.0}, {0.2, 0.1}, {0.1, -0.05}, {0.0, 0.03}, {0.05, 0.02}};
        p.correlation = {c};
      }
      const auto delayed = noiseFreePhases(p, axis, signal, delta);
      const auto moved = noiseFreePhases(p, axis, later);
      const auto still = noiseFreePhases(p, axis, signal);
      for (std::size_t f = 0; f < 2; ++f) {
        EXPECT_NEAR(delayed[f], moved[f], 1e-9) << N << " " << f;
        if (w == Waveform::Sine) {  // no wiggling: depth shift k delta, exactly, any delta
          const double shift = wrapSigned(delayed[f] - still[f], 2 * M_PI);
          EXPECT_NEAR(k * shift / (2 * M_PI * p.frequencies_Hz[f]), k * delta, 1e-9);
          const double odd = 37.3e-12;  // not a whole number of bins
          const double oddShift =
              wrapSigned(noiseFreePhases(p, axis, signal, odd)[f] - still[f], 2 * M_PI);
          EXPECT_NEAR(k * oddShift / (2 * M_PI * p.frequencies_Hz[f]), k * odd, 1e-9);
        }
      }
    }
  }
  // Through the stream: a constant delay map shifts cwtof_depth by k delta
  // (float32 outputs) and leaves the multipath error (the scene's) alone.
  const TransientVolume v = uniform(4, 3, 100.0f);
  CwTofParams p = noiseFree();
  const auto plain = runCwTof(v, p, 1);
  p.delay_map = constantMap(4, 3, 150e-12);
  const auto shifted = runCwTof(v, p, 1);
  const double dk = v.axis().depthPerSecond_m_per_s() * 150e-12;
  for (std::size_t i = 0; i < 12; ++i) {
    EXPECT_NEAR(output(shifted, "cwtof_depth").data[i] - output(plain, "cwtof_depth").data[i], dk,
                2e-6);
  }
}

TEST(CwTofDeviceTest, ConstantGainAndOffsetCancelInTheDft) {
  const TransientVolume v = varied(6, 5);
  for (int32_t N : {3, 4, 7}) {
    CwTofParams p = noiseFree();
    p.phase_steps = N;
    p.ambient_e = 30.0;
    const auto plain = runCwTof(v, p, 1);
    p.gain_map = constantMap(6, 5, 1.37);
    p.offset_map = constantMap(6, 5, -45.0);
    const auto scaled = runCwTof(v, p, 1);
    for (std::size_t i = 0; i < 30; ++i) {
      EXPECT_NEAR(output(scaled, "cwtof_depth").data[i], output(plain, "cwtof_depth").data[i],
                  2e-6);
      EXPECT_NEAR(output(scaled, "cwtof_amplitude").data[i],
                  1.37 * output(plain, "cwtof_amplitude").data[i],
                  1e-4 * output(plain, "cwtof_amplitude").data[i]);
    }
  }
}

TEST(CwTofDeviceTest, TwoTapsWithUnequalGainsGiveTheClosedFormPhasorBias) {
  const TransientVolume v = uniform(3, 2, 400.0f);
  CwTofParams one = noiseFree();
  one.ambient_e = 300.0;
  const auto single = runCwTof(v, one, 1);
  CwTofParams p = one;
  p.taps = 2;
  p.output_taps = true;
  p.tap_a_gain = 1.2;
  p.tap_b_gain = 0.8;
  const auto two = runCwTof(v, p, 1);
  const std::vector<float>& taps = array(two, "cwtof_raw_taps").data;  // (1, 4, 2, 2, 3)
  const std::vector<float>& ideal = array(single, "cwtof_raw").data;   // (1, 4, 2, 3)
  const double S = 400.0 * 1.3;
  const double c = 0.5 * (S + 300.0);  // each tap's DC part
  for (std::size_t px = 0; px < 6; ++px) {
    const auto tap = [&](int n, int t) { return double(taps[(n * 2 + t) * 6 + px]); };
    // 4 phases from 2 exposures: theta + pi read from tap B of exposure theta.
    const std::complex<double> z(tap(0, 0) - tap(0, 1), tap(1, 0) - tap(1, 1));
    const std::complex<double> s(ideal[0 * 6 + px] - c, ideal[1 * 6 + px] - c);  // AC parts
    const std::complex<double> closed = (1.2 - 0.8) * c * std::complex<double>(1, 1) + 2.0 * s;
    EXPECT_NEAR(std::abs(z - closed), 0.0, 1e-3 * std::abs(closed)) << px;
    EXPECT_GT(std::abs(std::arg(z) - std::arg(s)), 0.05);  // the bias is there
    // The N-step difference A - B cancels it: the single tap's phase.
    EXPECT_NEAR(array(two, "cwtof_phase").data[px], array(single, "cwtof_phase").data[px], 1e-5);
  }
}

TEST(CwTofDeviceTest, AdcCodesAreBitExact) {
  CwTofParams p;
  p.adc_bits = 10;
  p.adc_gain_dn_per_e = 2.0;
  p.adc_offset_dn = 100.0;
  p.companding = {"", {0.0, 1000.0, 3000.0}, {0.0, 500.0, 1000.0}};
  struct Case {
    double raw_e, code;
    bool saturated;
  };
  // v = 2 x + 100; below 1000 halved, above 500 + (v - 1000) / 4; round half away from zero.
  const Case cases[] = {{10.0, 60.0, false},    {600.0, 575.0, false}, {0.2, 50.0, false},
                        {1.5, 52.0, false},     {1.1, 51.0, false},    {1450.0, 1000.0, false},
                        {1450.5, 1000.0, true}, {-50.5, 0.0, true},    {-50.0, 0.0, false}};
  for (const Case& c : cases) {
    bool saturated = false;
    EXPECT_EQ(cwtofAdc(p, c.raw_e, saturated), c.code) << c.raw_e;
    EXPECT_EQ(saturated, c.saturated) << c.raw_e;
  }
  p.companding = {};
  p.adc_bits = 8;  // linear, clipped at 255
  const Case linear[] = {{77.25, 255.0, false},
                         {77.75, 255.0, true},
                         {-49.8, 0.0, false},
                         {-50.25, 0.0, true},
                         {3.2, 106.0, false}};
  for (const Case& c : linear) {
    bool saturated = false;
    EXPECT_EQ(cwtofAdc(p, c.raw_e, saturated), c.code) << c.raw_e;
    EXPECT_EQ(saturated, c.saturated) << c.raw_e;
  }
}

TEST(CwTofDeviceTest, FullWellAndClippingFlagThePixelAndNaNItsDeviceDepth) {
  TransientVolume v = makeVolume(3, 1, 0.0, 20e-12, 200);
  v.at(0, 0, 80, 0) = 5000.0f;  // a tap reaches the full well
  v.at(0, 1, 80, 0) = 500.0f;   // below it
  v.at(0, 2, 80, 0) = 3000.0f;  // below the well, above the ADC's range
  CwTofParams p = noiseFree();
  p.full_well_e = 4000.0;
  p.adc_bits = 12;
  p.adc_gain_dn_per_e = 1.0;
  const auto outs = runCwTof(v, p, 1);
  const std::vector<float>& saturated = output(outs, "cwtof_saturated").data;
  const std::vector<float>& depth = output(outs, "cwtof_device_depth").data;
  EXPECT_EQ(saturated, (std::vector<float>{1.0f, 0.0f, 0.0f}));
  EXPECT_TRUE(std::isnan(depth[0]));
  EXPECT_NEAR(depth[1], output(outs, "cwtof_depth").data[1], 5e-3);  // 1 e- per DN: rounding
  float maxRaw = 0.0f;
  for (int j = 0; j < 4; ++j) maxRaw = std::max(maxRaw, array(outs, "cwtof_raw").data[j * 3]);
  EXPECT_EQ(maxRaw, 4000.0f);  // the well holds
  p.adc_bits = 11;             // 2047 DN: pixel 2's brightest raw clips
  const auto clipped = runCwTof(v, p, 1);
  EXPECT_EQ(output(clipped, "cwtof_saturated").data, (std::vector<float>{1.0f, 0.0f, 1.0f}));
  EXPECT_TRUE(std::isnan(output(clipped, "cwtof_device_depth").data[2]));
  EXPECT_FALSE(std::isnan(output(clipped, "cwtof_device_depth").data[1]));
}

TEST(CwTofDeviceTest, SuppressionKeepsTheDifferenceAndMovesSaturation) {
  const TransientVolume v = uniform(3, 2, 300.0f);
  CwTofParams p = noiseFree();
  p.taps = 2;
  p.output_taps = true;
  p.ambient_e = 6400.0;
  p.full_well_e = 3300.0;
  const auto plain = runCwTof(v, p, 1);
  p.ambient_suppression = 0.8;
  const auto suppressed = runCwTof(v, p, 1);
  // Without: the taps (3395 e- of DC alone) fill the well.
  EXPECT_EQ(output(plain, "cwtof_saturated").data[0], 1.0f);
  EXPECT_EQ(output(suppressed, "cwtof_saturated").data[0], 0.0f);
  p.full_well_e = 0.0;
  p.ambient_suppression = 0.0;
  const auto unlimited = runCwTof(v, p, 1);
  p.ambient_suppression = 0.8;
  const auto removed = runCwTof(v, p, 1);
  const std::vector<float>&a = array(unlimited, "cwtof_raw").data,
        &b = array(removed, "cwtof_raw").data;
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(b[i], a[i], 1e-6 * std::fabs(a[i]) + 1e-3);
  const std::vector<float>&ta = array(unlimited, "cwtof_raw_taps").data,
        &tb = array(removed, "cwtof_raw_taps").data;
  for (std::size_t j = 0; j < ta.size() / 12; ++j) {  // raw j of pixel 0: taps at 2 j, 2 j + 1
    const double lo = std::min(ta[(2 * j) * 6], ta[(2 * j + 1) * 6]);
    EXPECT_NEAR(tb[(2 * j) * 6], ta[(2 * j) * 6] - 0.8 * lo, 1e-3);
  }
}

TEST(CwTofDeviceTest, FixedPatternComesFromItsOwnSeed) {
  const TransientVolume v = varied(8, 8);
  CwTofParams p;
  p.taps = 2;
  p.fpn_seed = 42;
  p.delay_sigma_s = 50e-12;
  p.gain_sigma = 0.02;
  p.offset_sigma_e = 3.0;
  const auto a = runCwTof(v, p, 1), b = runCwTof(v, p, 2);
  for (const char* map :
       {"cwtof_delay_map", "cwtof_gain_map", "cwtof_gain_map_b", "cwtof_offset_map"}) {
    EXPECT_EQ(output(a, map).data, output(b, map).data) << map;
  }
  EXPECT_NE(array(a, "cwtof_raw").data, array(b, "cwtof_raw").data);  // the noise differs
  p.fpn_seed = 43;
  EXPECT_NE(output(runCwTof(v, p, 1), "cwtof_delay_map").data, output(a, "cwtof_delay_map").data);
  // The pattern's spread is its sigma (64 pixels: within 4 standard errors).
  const CwTofFixedPattern fp = cwtofFixedPattern(p, 8, 8);
  double sum2 = 0.0;
  for (double d : fp.delay_s) sum2 += d * d;
  EXPECT_NEAR(std::sqrt(sum2 / 64), 50e-12, 4 * 50e-12 / std::sqrt(128.0));
  // Setting one sigma leaves the others' pattern as it was.
  CwTofParams delayOnly = p;
  delayOnly.gain_sigma = delayOnly.offset_sigma_e = 0.0;
  EXPECT_EQ(cwtofFixedPattern(delayOnly, 8, 8).delay_s, fp.delay_s);
}

TEST(CwTofDeviceTest, RawTimeStampsFollowTheCaptureOrder) {
  CwTofParams p;
  p.frequencies_Hz = {80e6, 16e6, 120e6};
  p.phase_steps = 3;
  p.integration_time_s = 1e-3;
  p.readout_gap_s = 0.5e-3;
  const auto start = cwtofRawStartTimes_s(p);
  for (std::size_t j = 0; j < 9; ++j) EXPECT_DOUBLE_EQ(start[j], 1.5e-3 * j);  // f-major
  p.capture_order = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}, {0, 2}, {1, 2}, {2, 2}};
  const auto stepMajor = cwtofRawStartTimes_s(p);
  EXPECT_DOUBLE_EQ(stepMajor[1 * 3 + 2], 7 * 1.5e-3);  // (f 1, n 2) is the 8th raw
  p.capture_order.pop_back();
  EXPECT_THROW(checkCwTofDevice(p), InputError);
}

TEST(CwTofDeviceTest, NoiseTableDrawsItsSamplesInLaw) {
  // Columns 0..4: noise-free raws 100, 110, .., 140 e- (ambient 200, no
  // light, an offset per column); column 5 at 150 is outside the table.
  const int32_t W = 6, H = 300;
  const TransientVolume v = makeVolume(W, H, 0.0, 20e-12, 50);
  CwTofParams p;
  p.ambient_e = 200.0;
  p.offset_map = constantMap(W, H, 0.0);
  for (int32_t px = 0; px < W * H; ++px) p.offset_map.values[px] = 10.0 * (px % W);
  p.noise_model = CwTofNoiseModel::Table;
  p.noise_table.first_mean_e = 100;
  p.noise_table.samples.resize(41);
  const int kSamples = 40;
  for (int level = 0; level < 5; ++level) {  // uneven multiplicities over m - 6 .. m + 6
    for (int k = 0; k < kSamples; ++k) {
      p.noise_table.samples[10 * level].push_back(100 + 10 * level - 6 + (k * k) % 13);
    }
  }
  const std::vector<float> raw = array(runCwTof(v, p, 3), "cwtof_raw").data;
  const std::size_t HW = static_cast<std::size_t>(W) * H;
  // Per level: counts of each value against draws x multiplicity / 40; and
  // against the same values equally likely (a wrong law).
  double x2 = 0.0, wrong = 0.0;
  int dof = 0;
  for (int level = 0; level < 5; ++level) {
    std::map<double, int> expected, observed;
    for (double s : p.noise_table.samples[10 * level]) ++expected[s];
    int draws = 0;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (static_cast<int>(i % HW) % W != level) continue;
      ASSERT_TRUE(expected.count(raw[i])) << raw[i];
      ++observed[raw[i]];
      ++draws;
    }
    for (const auto& [value, count] : expected) {
      const double e = double(draws) * count / kSamples, e0 = double(draws) / expected.size();
      const double o = observed[value];
      x2 += (o - e) * (o - e) / e;
      wrong += (o - e0) * (o - e0) / e0;
    }
    dof += static_cast<int>(expected.size()) - 1;
  }
  std::printf("noise table: chi-square %.1f on %d dof; equal weights: %.1f\n", x2, dof, wrong);
  EXPECT_LT(x2, dof + 4.0 * std::sqrt(2.0 * dof));
  EXPECT_GT(wrong, dof + 4.0 * std::sqrt(2.0 * dof));
  for (std::size_t i = 5; i < raw.size(); i += W) EXPECT_EQ(raw[i], 150.0f);  // outside: no noise
}

TEST(CwTofDeviceTest, BadParametersAreInputErrors) {
  const TransientVolume v = uniform(4, 3, 10.0f);
  const auto fails = [&](const auto& change) {
    CwTofParams p;
    change(p);
    EXPECT_THROW(runCwTof(v, p, 1), InputError);
  };
  fails([](CwTofParams& p) { p.gain_map = constantMap(3, 4, 1.0); });  // W, H swapped
  fails([](CwTofParams& p) { p.adc_bits = 25; });
  fails([](CwTofParams& p) { p.taps = 3; });
  fails([](CwTofParams& p) { p.ambient_suppression = 0.5; });  // one tap
  fails([](CwTofParams& p) {
    p.adc_bits = 12;
    p.companding = {"", {0.0, 10.0, 5.0}, {0.0, 1.0, 2.0}};
  });
}

}  // namespace
}  // namespace tofsim::sensors
