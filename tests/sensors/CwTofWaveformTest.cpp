// Measured correlation waveforms (CwTofWaveform.h): exact bin means, the
// N-step aliasing law, the built-in sine's bytes, the square wave's wiggling
// error in closed form, the modulation contrast, and bad waveforms.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstring>
#include <random>

#include "TestVolumes.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/util/Error.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::sensors {
namespace {

using test::makeVolume;
using test::output;
using cd = std::complex<double>;
constexpr double kC = kSpeedOfLight_m_per_s;

CwTofParams measured(std::vector<double> freqs, CorrelationWaveform w) {
  CwTofParams p;
  p.frequencies_Hz = std::move(freqs);
  p.shot_noise = false;
  p.waveform = Waveform::Measured;
  p.correlation = {std::move(w)};
  return p;
}

CorrelationWaveform fourier(std::vector<cd> c) {
  CorrelationWaveform w;
  w.harmonics = std::move(c);
  return w;
}

CorrelationWaveform samples(std::vector<double> phases, std::vector<double> values) {
  CorrelationWaveform w;
  w.phases_rad = std::move(phases);
  w.values = std::move(values);
  return w;
}

double wrap2Pi(double a) { return a - 2 * M_PI * std::floor(a / (2 * M_PI)); }
double wrapPi(double a) { return a - 2 * M_PI * std::round(a / (2 * M_PI)); }

// Against a fine midpoint sum over an interval of 1.3 periods (both forms).
TEST(CwTofWaveformTest, BinMeanIsExact) {
  const PhaseCorrelation f(fourier({{0.8, 0.3}, {0.0, 0.0}, {-0.1, 0.05}, {0.02, 0.0}}));
  const PhaseCorrelation s(samples({0.0, 0.5, 1.9, 2.0, 4.4, 6.1}, {3, 7, -1, 0, 2.5, 5}));
  for (const PhaseCorrelation* rho : {&f, &s}) {
    for (const auto& [a, b] : {std::pair{-0.7, 7.5}, std::pair{1.95, 2.3}, std::pair{5.0, 5.01}}) {
      const int n = 400000;
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += rho->value(a + (i + 0.5) * (b - a) / n);
      EXPECT_NEAR(rho->mean(a, b), sum / n, 1e-9) << a << " " << b;
    }
  }
  // The shape: mean 0 and max |rho| = 1 (the samples' extreme is at a knot).
  EXPECT_NEAR(s.mean(0.3, 0.3 + 2 * M_PI), 0.0, 1e-15);
  double largest = 0.0;
  for (double knot : {0.0, 0.5, 1.9, 2.0, 4.4, 6.1})
    largest = std::max(largest, std::fabs(s.value(knot)));
  EXPECT_NEAR(largest, 1.0, 1e-15);
}

// The N-step law. With rho(x) = sum_k Re(c_k e^{ikx}) = sum_k (c_k e^{ikx} +
// conj(c_k) e^{-ikx}) / 2 and C_n = B + A rho(phi - theta_n), theta_n =
// 2 pi n / N: sum_n C_n e^{i theta_n} = (N A / 2) [sum_{k = 1 mod N} c_k
// e^{ik phi} + sum_{k = -1 mod N} conj(c_k) e^{-ik phi}] (sum_n e^{i(1 -+
// k) theta_n} = N exactly when k = +-1 mod N, else 0; B drops out). So the
// phase is arg of that: for harmonics 3 and 5, N = 3 aliases the 5th (5 = -1
// mod 3, conjugated), N = 4 the 3rd (= -1) and the 5th (= 1), N = 5 neither.
// Each bin [t0, t1) adds its energy E_t times harmonic k's bin mean: c_k e^{ik
// phi_mid} sin(k h) / (k h), h = pi f (t1 - t0).
TEST(CwTofWaveformTest, PhaseFollowsTheAliasingLaw) {
  std::mt19937_64 rng(25);
  std::uniform_real_distribution<double> angle(0.0, 2 * M_PI);
  const std::vector<cd> c = {std::polar(1.0, angle(rng)), 0.0, std::polar(0.1, angle(rng)), 0.0,
                             std::polar(0.05, angle(rng))};
  const double f = 50e6, w = 25e-12;  // 800 bins: one period
  TimeAxis axis;
  axis.start_s = 0.37e-9;
  axis.bin_width_s = w;
  axis.bins = 800;
  const std::vector<std::vector<std::pair<int, double>>> pixels = {
      {{17, 1.0}}, {{130, 5.0}}, {{333, 2.0}}, {{501, 1.0}}, {{777, 3.0}}, {{90, 4.0}, {420, 1.5}}};
  for (int32_t N : {3, 4, 5}) {
    CwTofParams p = measured({f}, fourier(c));
    p.phase_steps = N;
    double largestAlias = 0.0, worst = 0.0;
    for (const auto& returns : pixels) {
      std::vector<double> signal(axis.bins, 0.0);
      cd law = 0.0, fundamental = 0.0;
      for (const auto& [bin, energy] : returns) {
        signal[bin] = energy;
        const double t0 = axis.binStart_s(bin), t1 = t0 + w;
        const double mid = M_PI * f * (t0 + t1), h = M_PI * f * (t1 - t0);
        for (int k = 1; k <= static_cast<int>(c.size()); ++k) {
          const cd term = energy * c[k - 1] * std::polar(std::sin(k * h) / (k * h), k * mid);
          if (k % N == 1) law += term;
          if (k % N == N - 1) law += std::conj(term);
          if (k == 1) fundamental += term;
        }
      }
      const double phase = noiseFreePhases(p, axis, signal)[0];
      const double residual = std::fabs(wrapPi(phase - wrap2Pi(std::arg(law))));
      EXPECT_LT(residual, 1e-9) << "N = " << N;
      worst = std::max(worst, residual);
      largestAlias = std::max(largestAlias, std::fabs(wrapPi(phase - std::arg(fundamental))));
    }
    std::printf("N = %d: |phase - aliasing law| <= %.2g rad, harmonics move it by %.4f rad\n", N,
                worst, largestAlias);
    // The harmonics move the phase where they alias, and only there.
    if (N == 5) {
      EXPECT_LT(largestAlias, 1e-12);
    } else {
      EXPECT_GT(largestAlias, 0.02) << "N = " << N;
    }
  }
}

// A few pixels of several returns, ambient, shot and read noise, two frequencies.
TransientVolume noisyScene() {
  TransientVolume v = makeVolume(3, 2, 1.3e-9, 20e-12, 64);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<float> energy(0.0f, 40.0f);
  for (float& e : v.values()) e = energy(rng);
  return v;
}

std::vector<SensorOutput> run(const CwTofParams& base, Waveform waveform,
                              std::vector<CorrelationWaveform> correlation, bool noise) {
  CwTofParams p = base;
  p.waveform = waveform;
  p.correlation = std::move(correlation);
  p.shot_noise = noise;
  p.read_noise_e = noise ? 2.0 : 0.0;
  return runCwTof(noisyScene(), p, 11);
}

TEST(CwTofWaveformTest, FourierCosineGivesTheSinesBytes) {
  CwTofParams p;
  p.frequencies_Hz = {20e6, 50e6};
  p.ambient_e = 50.0;
  const auto sine = run(p, Waveform::Sine, {}, true);
  const auto cosine = run(p, Waveform::Measured, {fourier({1.0})}, true);
  ASSERT_EQ(sine.size(), cosine.size());
  for (std::size_t i = 0; i < sine.size(); ++i) {
    EXPECT_EQ(sine[i].name, cosine[i].name);
    ASSERT_EQ(sine[i].data.size(), cosine[i].data.size()) << sine[i].name;
    EXPECT_EQ(std::memcmp(sine[i].data.data(), cosine[i].data.data(), 4 * sine[i].data.size()), 0)
        << sine[i].name;
  }
}

// M samples of cos, linear in between: |interpolant - cos| <= (2 pi / M)^2 / 8
// (the interpolation error bound, |cos''| <= 1), so each raw differs from the
// sine's by at most 0.5 sum E x that (4.7e-6 relative at M = 1024), plus float
// rounding; the phase by the images k = M +- 1 (amplitude ~1 / M^2), far below
// the 2e-5 rad allowed.
TEST(CwTofWaveformTest, DenseCosineSamplesGiveTheSineWithinTheInterpolationBound) {
  const int M = 1024;
  std::vector<double> phases, values;
  for (int j = 0; j < M; ++j) {
    phases.push_back(2 * M_PI * j / M);
    values.push_back(std::cos(2 * M_PI * j / M));
  }
  CwTofParams p;
  p.frequencies_Hz = {20e6, 50e6};
  const auto sine = run(p, Waveform::Sine, {}, false);
  const auto table = run(p, Waveform::Measured, {samples(phases, values)}, false);
  const auto& a = test::array(sine, "cwtof_raw").data;
  const auto& b = test::array(table, "cwtof_raw").data;
  const double bound = 0.5 * 64 * 40.0 * std::pow(2 * M_PI / M, 2) / 8;
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, static_cast<double>(std::fabs(a[i] - b[i])));
    EXPECT_NEAR(a[i], b[i], bound + 1e-6 * std::fabs(a[i])) << i;  // + float32 rounding
  }
  const auto& pa = test::array(sine, "cwtof_phase").data;
  const auto& pb = test::array(table, "cwtof_phase").data;
  for (std::size_t i = 0; i < pa.size(); ++i) EXPECT_LT(std::fabs(wrapPi(pa[i] - pb[i])), 2e-5);
  std::printf("dense cosine samples: max |raw difference| %.3g e- (bound %.3g)\n", worst, bound);
}

// The README's closed form for a square wave (triangle correlation) at N = 4:
// true phase theta = q pi / 2 + r, r in [0, pi / 2), estimate q pi / 2 +
// atan2(2 r / pi, 1 - 2 r / pi); depth error (estimate - theta) R / (2 pi).
double squareError_m(double theta, double range) {
  const double q = std::floor(theta / (M_PI / 2)), x = (theta - q * M_PI / 2) / (M_PI / 2);
  return (q * M_PI / 2 + std::atan2(x, 1 - x) - theta) * range / (2 * M_PI);
}

TEST(CwTofWaveformTest, SquareWaveWigglingMatchesItsClosedForm) {
  const double f = 20e6, range = kC / (2 * f);
  CwTofParams p;
  p.frequencies_Hz = {f};
  p.waveform = Waveform::Square;
  const std::vector<double> square = wigglingError_m(p, kC / 2);
  // The same triangle as two samples, linear in between.
  const std::vector<double> triangle =
      wigglingError_m(measured({f}, samples({0.0, M_PI}, {1.0, -1.0})), kC / 2);
  p.waveform = Waveform::Sine;
  const std::vector<double> sine = wigglingError_m(p, kC / 2);
  const int S = kWigglingSweepPoints;
  ASSERT_EQ(square.size(), static_cast<std::size_t>(S));
  double maxAbs = 0.0, sum2 = 0.0;
  for (int j = 0; j < S; ++j) {
    const double expected = squareError_m(2 * M_PI * (j + 0.5) / S, range);
    EXPECT_NEAR(square[j], expected, 1e-12) << j;
    EXPECT_NEAR(triangle[j], expected, 1e-12) << j;
    EXPECT_LT(std::fabs(sine[j]), 1e-12) << j;
    maxAbs = std::max(maxAbs, std::fabs(expected));
    sum2 += expected * expected;
  }
  // The closed form's extreme: x = (1 - sqrt(4 / pi - 1)) / 2, 0.0710 rad.
  const double x = (1 - std::sqrt(4 / M_PI - 1)) / 2;
  const double peak = std::fabs(std::atan2(x, 1 - x) - M_PI / 2 * x) * range / (2 * M_PI);
  // The sweep points miss the extreme by up to pi / 1024 rad (3.9e-6 m measured).
  EXPECT_NEAR(maxAbs, peak, 1e-5);
  EXPECT_GT(maxAbs, 0.08);  // 8.5 cm at 20 MHz
  // The sensor's output: the same numbers (float) and their statistics.
  TransientVolume v = makeVolume(1, 1, 0.0, 10e-12, 8);
  p.waveform = Waveform::Square;
  const auto outs = runCwTof(v, p, 1);
  const SensorOutput& o = test::array(outs, "cwtof_wiggling_error");
  EXPECT_EQ(o.shape, (std::vector<int64_t>{1, S}));
  for (int j = 0; j < S; ++j) EXPECT_NEAR(o.data[j], square[j], 1e-8);
  const auto attribute = [&](const std::string& name) {
    for (const auto& [key, value] : o.attributes) {
      if (key == name) return value;
    }
    ADD_FAILURE() << "no attribute " << name;
    return 0.0;
  };
  EXPECT_NEAR(attribute("max_abs_error_m"), maxAbs, 1e-12);
  EXPECT_NEAR(attribute("rms_error_m"), std::sqrt(sum2 / S), 1e-12);
  EXPECT_NEAR(attribute("max_abs_error_20MHz_m"), maxAbs, 1e-12);
  EXPECT_NEAR(attribute("mean_error_20MHz_m"), 0.0, 1e-12);  // odd about each quarter period
  std::printf("square wave, N = 4, 20 MHz: max |wiggling| %.6f m (closed form %.6f), RMS %.6f m\n",
              attribute("max_abs_error_m"), peak, attribute("rms_error_m"));
}

// The wiggling at each pixel's true depth (cwtof_wiggling_error_map): a
// noise-free single return there, whatever light the pixel got, so the map
// is the square wave's closed-form error at each depth (and 0 for the sine);
// a pixel without a true depth is NaN.
TEST(CwTofWaveformTest, WigglingMapIsTheClosedFormAtEachPixelsTrueDepth) {
  const double f = 20e6, range = kC / (2 * f);
  const int32_t W = 16;
  TransientVolume v = makeVolume(W, 1, 0.0, 10e-12, 8);
  for (std::size_t i = 0; i < v.size(); ++i) v.data()[i] = 1.0f + 0.1f * (i % 5);  // any light
  Image gt(W, 1, 1);
  for (int32_t x = 1; x < W; ++x) gt.at(0, x, 0) = static_cast<float>(0.37 + 0.443 * x);
  CwTofParams p;
  p.frequencies_Hz = {f};
  p.shot_noise = false;
  double maxAbs = 0.0;
  for (Waveform waveform : {Waveform::Square, Waveform::Sine}) {
    p.waveform = waveform;
    CwTofReferences refs;
    refs.groundTruthDepth_m = &gt;
    const auto outs = runCwTof(v, p, 1, refs);
    const SensorOutput& map =
        test::output(outs, "cwtof_wiggling_error_map", SensorOutput::Kind::Image);
    EXPECT_TRUE(std::isnan(map.data[0]));  // no true depth
    for (int32_t x = 1; x < W; ++x) {
      const double theta = 2 * M_PI * f * gt.at(0, x, 0) / (kC / 2);
      const double expected =
          waveform == Waveform::Square ? squareError_m(std::fmod(theta, 2 * M_PI), range) : 0.0;
      EXPECT_NEAR(map.data[x], expected, 2e-7) << x;
      if (waveform == Waveform::Square) maxAbs = std::max(maxAbs, std::fabs(expected));
    }
  }
  EXPECT_GT(maxAbs, 0.02);  // the square wave's error is there to be found
}

TEST(CwTofWaveformTest, ContrastScalesTheAcPartOnly) {
  CwTofParams p = measured({20e6}, fourier({{0.3, 0.4}, 0.0, 0.02}));
  const auto full = runCwTof(noisyScene(), p, 1);
  p.modulation_contrast = 0.6;
  const auto low = runCwTof(noisyScene(), p, 1);
  const auto& a = output(full, "cwtof_amplitude").data;
  const auto& b = output(low, "cwtof_amplitude").data;
  const auto& pa = test::array(full, "cwtof_phase").data;
  const auto& pb = test::array(low, "cwtof_phase").data;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(b[i], 0.6 * a[i], 1e-4 * a[i]);
    EXPECT_NEAR(pb[i], pa[i], 1e-5);
  }
  // The mean over the N steps is 0.5 (E + ambient) at any contrast.
  const auto& ra = test::array(full, "cwtof_raw").data;
  const auto& rb = test::array(low, "cwtof_raw").data;
  const std::size_t HW = 6;
  for (std::size_t px = 0; px < HW; ++px) {
    double sa = 0.0, sb = 0.0;
    for (int n = 0; n < 4; ++n) {
      sa += ra[n * HW + px];
      sb += rb[n * HW + px];
    }
    EXPECT_NEAR(sa, sb, 1e-3);
  }
}

TEST(CwTofWaveformTest, BadWaveformsAreInputErrors) {
  EXPECT_NE(waveformProblem(fourier({0.0, 0.0})).find("zero energy"), std::string::npos);
  EXPECT_NE(waveformProblem(samples({0, 1, 2}, {4, 4, 4})).find("zero energy"), std::string::npos);
  EXPECT_NE(waveformProblem(samples({0, 1}, {1, NAN})).find("not finite"), std::string::npos);
  EXPECT_NE(waveformProblem(samples({0, 7}, {1, 0})).find("[0, 2 pi)"), std::string::npos);
  EXPECT_NE(waveformProblem(samples({1, 1}, {1, 0})).find("increase"), std::string::npos);
  EXPECT_EQ(waveformProblem(samples({0, 1}, {1, 0})), "");
  const TransientVolume v = makeVolume(1, 1, 0.0, 10e-12, 8);
  EXPECT_THROW(runCwTof(v, measured({20e6}, fourier({0.0})), 1), InputError);
  CwTofParams two = measured({20e6, 30e6, 50e6}, fourier({1.0}));
  two.correlation.push_back(fourier({1.0}));  // 2 waveforms for 3 frequencies
  EXPECT_THROW(runCwTof(v, two, 1), InputError);
  two.correlation.push_back(fourier({0.5, 0.1}));
  EXPECT_NO_THROW(runCwTof(v, two, 1));
  two.waveform = Waveform::Sine;  // waveforms given, but not used
  EXPECT_THROW(runCwTof(v, two, 1), InputError);
}

}  // namespace
}  // namespace tofsim::sensors
