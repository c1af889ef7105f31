// Gated 1-bit frames (gated_frames, pulses_per_frame, gate_step,
// gate_positions) and counter depth (counter_bits): a frame's latch fires
// with P = 1 - exp(-M Lambda_g), Lambda_g the expected detections per pulse
// inside the gate, so a pixel's sum over N_f frames is Binomial(N_f, P).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "TestVolumes.h"
#include "support/ChiSquare.h"
#include "support/ShortNumber.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {
namespace {

using test::array;
using test::makeVolume;
using tofsim::test::sci;

constexpr double kW = 10e-12;
constexpr int32_t kBins = 120;

TransientVolume uniformVolume(int32_t side, const std::vector<double>& signal) {
  TransientVolume v = makeVolume(side, side, 0.0, kW, kBins);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      for (int t = 0; t < kBins; ++t) v.at(y, x, t, 0) = static_cast<float>(signal[t]);
  return v;
}

SpadParams frames(int64_t nFrames, int64_t pulses) {
  SpadParams p;
  p.cycles = 100;
  p.pde = 1.0;
  p.gate_start_s = 10 * kW;
  p.gate_width_s = 40 * kW;
  p.gated_frames = nFrames;
  p.pulses_per_frame = pulses;
  return p;
}

struct Moments {
  double mean, variance;
};
Moments moments(const std::vector<float>& c, std::size_t stride, std::size_t k) {
  double n = 0.0, sum = 0.0, squares = 0.0;
  for (std::size_t i = k; i < c.size(); i += stride, n += 1.0) sum += c[i];
  const double mean = sum / n;
  for (std::size_t i = k; i < c.size(); i += stride) squares += (c[i] - mean) * (c[i] - mean);
  return {mean, squares / (n - 1.0)};
}

// Lambda_g = 0.006 signal photons (inside the gate) + 1e7 /s dark counts x
// 400 ps = 0.01 per pulse, written here from the parameters; M = 50 gives P
// = 1 - e^-0.5.
TEST(SpadGatedFramesTest, MeanAndVarianceAreThoseOfTheLatchBinomial) {
  std::vector<double> signal(kBins, 0.0);
  signal[20] = 0.006;
  SpadParams p = frames(200, 50);
  p.dark_count_rate_per_s = 1e7;
  const auto outs = runSpad(uniformVolume(64, signal), p, 3);
  const SensorOutput& c = array(outs, "spad_gated_counts");
  ASSERT_EQ(c.shape, (std::vector<int64_t>{64, 64, 1}));
  const double lambda = 0.006 + 1e7 * 40 * kW, n = 64.0 * 64.0, N = 200.0;
  const auto law = [&](double M) { return -std::expm1(-M * lambda); };
  const Moments m = moments(c.data, 1, 0);
  const double P = law(50.0), var = N * P * (1.0 - P);
  const double z = (m.mean - N * P) / std::sqrt(var / n);
  const double chi = (n - 1.0) * m.variance / var;  // ~ chi-square(n - 1)
  RecordProperty("mean_z", sci(z));
  RecordProperty("variance_chi2", sci(chi));
  EXPECT_LT(std::fabs(z), 4.0);
  EXPECT_LT(chi, tofsim::test::chiSquareQuantile(static_cast<int>(n) - 1, 3.09));
  EXPECT_GT(chi, tofsim::test::chiSquareQuantile(static_cast<int>(n) - 1, -3.09));
  // M 10 % off, or the latch read as a count of detections (N M Lambda), is rejected.
  EXPECT_GT(std::fabs(m.mean - N * law(55.0)) / std::sqrt(var / n), 4.0);
  EXPECT_GT(std::fabs(m.mean - N * 50.0 * lambda) / std::sqrt(var / n), 4.0);
  // The inversion recovers Lambda (its bias is O(1 / N_f), far below this).
  const Moments f = moments(array(outs, "spad_gated_flux").data, 1, 0);
  EXPECT_NEAR(f.mean, lambda, 0.02 * lambda);
}

// The sweep: gate position k (the gate of 10 bins with 2-bin ramps moved by
// k bins) sees Lambda_k = sum_i g_i(k) flux_i, the transient convolved with
// the gate, here from a midpoint-rule integral of the gate written out.
double gateAt(double t, double start, double end, double ramp) {
  return std::clamp(std::min((t - (start - 0.5 * ramp)) / ramp, ((end + 0.5 * ramp) - t) / ramp),
                    0.0, 1.0);
}

TEST(SpadGatedFramesTest, TheSweepSamplesTheTransientConvolvedWithTheGate) {
  std::vector<double> signal(kBins, 0.0);
  for (int t = 50; t < 60; ++t) signal[t] = 0.002 * (1 + (t - 50) % 3);
  SpadParams p = frames(1000, 20);
  p.gate_start_s = 20 * kW;
  p.gate_width_s = 10 * kW;
  p.gate_rise_s = p.gate_fall_s = 2 * kW;
  p.gate_step_s = kW;
  p.gate_positions = 60;
  const auto outs = runSpad(uniformVolume(16, signal), p, 4);
  const SensorOutput& c = array(outs, "spad_gated_counts");
  ASSERT_EQ(c.shape, (std::vector<int64_t>{16, 16, 60}));
  const double n = 256.0, N = 1000.0, M = 20.0;
  const auto expectedLambda = [&](int k, double shift) {
    const double start = p.gate_start_s + (k + shift) * kW, end = start + p.gate_width_s;
    double lambda = 0.0;
    for (int t = 0; t < kBins; ++t) {
      double g = 0.0;
      for (int j = 0; j < 1000; ++j) g += gateAt((t + (j + 0.5) / 1000) * kW, start, end, 2 * kW);
      lambda += signal[t] * g / 1000;
    }
    return lambda;
  };
  double chi = 0.0, shifted = 0.0, flat = 0.0;
  for (int k = 0; k < 60; ++k) {
    double sum = 0.0;
    for (std::size_t i = k; i < c.data.size(); i += 60) sum += c.data[i];
    const auto term = [&](double lambda) {
      const double P = -std::expm1(-M * lambda);
      if (P <= 0.0) return sum == 0.0 ? 0.0 : 1e300;
      return (sum - n * N * P) * (sum - n * N * P) / (n * N * P * (1.0 - P));
    };
    chi += term(expectedLambda(k, 0.0));
    shifted += term(expectedLambda(k, 0.5));
    // no sweep: every position the first one's gate
    flat += term(expectedLambda(0, 0.0));
  }
  RecordProperty("chi2", sci(chi));
  RecordProperty("chi2_half_step_late", sci(shifted));
  // Positions whose gate misses the light have P = 0 and count 0 exactly
  // (they add 0); the statistic has at most 60 degrees of freedom.
  EXPECT_LT(chi, tofsim::test::chiSquareQuantile(60, 3.09));
  EXPECT_GT(shifted, tofsim::test::chiSquareQuantile(60, 3.09));
  EXPECT_GT(flat, tofsim::test::chiSquareQuantile(60, 3.09));
}

TEST(SpadGatedFramesTest, CountersClipExactlyAtTwoToTheBitsMinusOne) {
  std::vector<double> signal(kBins, 0.0);
  signal[20] = 0.5;
  signal[30] = 0.05;
  SpadParams p = frames(100, 4);  // P ~ 0.9: ~90 of 100 frames
  p.cycles = 300;
  const TransientVolume v = uniformVolume(8, signal);
  const auto free = runSpad(v, p, 5);
  SpadParams clipped = p;
  clipped.counter_bits = 6;  // 63
  const auto outs = runSpad(v, clipped, 5);
  for (const char* name : {"spad_gated_counts", "spad_counts"}) {
    const std::vector<float>& a = array(free, name).data;
    const std::vector<float>& b = array(outs, name).data;
    ASSERT_EQ(a.size(), b.size());
    int64_t clips = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(b[i], std::min(a[i], 63.0f)) << name << " " << i;
      clips += a[i] > 63.0f;
    }
    EXPECT_GT(clips, 0) << name;  // the test sees counts above the depth
  }
  // A counter deep enough changes nothing.
  SpadParams deep = p;
  deep.counter_bits = 12;
  EXPECT_EQ(array(runSpad(v, deep, 5), "spad_counts").data, array(free, "spad_counts").data);
}

TEST(SpadGatedFramesTest, OwnStreamSameBytesForAnyThreadCountAndSpans) {
  std::vector<double> signal(kBins, 0.0);
  signal[25] = 0.01;
  SpadParams p = frames(50, 10);
  p.gate_step_s = 3 * kW;
  p.gate_positions = 5;
  const TransientVolume v = uniformVolume(12, signal);
  SpadParams off = p;
  off.gated_frames = 0;
  const auto base = runSpad(v, off, 6);
  EXPECT_EQ(findOutput(base, "spad_gated_counts", SensorOutput::Kind::Array), nullptr);
  std::vector<float> first;
  for (int threads : {1, 3}) {
    StreamOptions options;
    options.seed = 6;
    options.threads = threads;
    auto stream = openSpad(p, shapeOf(v), options);
    PixelSpan a = wholeVolume(v), b = a;
    a.pixelCount = 50;
    b.firstPixel = 50;
    b.pixelCount = 144 - 50;
    b.volume = v.data() + 50 * shapeOf(v).pixelFloats();
    stream->consume(a);
    stream->consume(b);
    const auto outs = stream->finish(nullptr);
    // The histogram path does not change with the frames on.
    EXPECT_EQ(array(outs, "spad_counts").data, array(base, "spad_counts").data);
    const std::vector<float>& c = array(outs, "spad_gated_counts").data;
    if (first.empty()) first = c;
    EXPECT_EQ(c, first) << threads << " threads";
  }
  EXPECT_EQ(first, array(runSpad(v, p, 6), "spad_gated_counts").data);
}

}  // namespace
}  // namespace tofsim::sensors
