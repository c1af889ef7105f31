#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "TestVolumes.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/util/Error.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::sensors {
namespace {

using test::makeVolume;
using test::output;
constexpr double kC = kSpeedOfLight_m_per_s;

CwTofParams noiseFree(std::vector<double> freqs) {
  CwTofParams p;
  p.frequencies_Hz = std::move(freqs);
  p.shot_noise = false;
  return p;
}

/// A 1x1 volume with 10 ps bins whose bin `centre` is centred on the round
/// trip time of `depth`.
TransientVolume singleReturn(double depth, int32_t bins, float energy) {
  const double w = 10e-12, t = 2.0 * depth / kC;
  TransientVolume v = makeVolume(1, 1, t - 100.5 * w, w, bins);
  v.at(0, 0, 100, 0) = energy;
  return v;
}

TEST(CwTofTest, SingleReturnGivesItsDepth) {
  for (double depth : {0.3, 3.3, 7.0}) {  // unambiguous range at 20 MHz: 7.49 m
    const auto outs = runCwTof(singleReturn(depth, 200, 1000.0f), noiseFree({20e6}), 1);
    EXPECT_NEAR(output(outs, "cwtof_depth").data[0], depth, 1e-3) << depth;
    // Amplitude: half the energy times the bin average of the phasor (sinc).
    const double half = M_PI * 20e6 * 10e-12;
    EXPECT_NEAR(output(outs, "cwtof_amplitude").data[0], 500.0 * std::sin(half) / half, 1e-3);
  }
  const auto outs = runCwTof(singleReturn(8.0, 200, 1000.0f), noiseFree({20e6}), 1);
  EXPECT_NEAR(output(outs, "cwtof_depth").data[0], 8.0 - kC / (2 * 20e6), 1e-3);  // wraps
}

TEST(CwTofTest, TwoReturnsGiveThePhaseOfThePhasorSum) {
  const double w = 10e-12, f = 30e6;
  TransientVolume v = makeVolume(1, 1, 0.0, w, 600);
  v.at(0, 0, 150, 0) = 700.0f;
  v.at(0, 0, 420, 0) = 400.0f;
  const auto outs = runCwTof(v, noiseFree({f}), 1);
  // Equal-width bins share the sinc factor: the phase is that of the centres' phasors.
  std::complex<double> sum = 700.0 * std::polar(1.0, 2 * M_PI * f * 150.5 * w) +
                             400.0 * std::polar(1.0, 2 * M_PI * f * 420.5 * w);
  double phase = std::arg(sum);
  if (phase < 0) phase += 2 * M_PI;
  EXPECT_NEAR(test::array(outs, "cwtof_phase").data[0], phase, 1e-6);
  EXPECT_NEAR(output(outs, "cwtof_depth").data[0], kC * phase / (4 * M_PI * f), 1e-4);
}

TEST(CwTofTest, TwoFrequenciesUnwrapBeyondOneFrequencysRange) {
  CwTofParams p = noiseFree({80e6, 100e6});  // ranges 1.87 m and 1.50 m; together 7.49 m
  EXPECT_NEAR(unwrapRange_m(p, kC / 2), kC / (2 * 20e6), 1e-9);
  for (double depth : {0.4, 2.2, 5.1, 7.2}) {
    const auto outs = runCwTof(singleReturn(depth, 200, 1000.0f), p, 1);
    EXPECT_NEAR(output(outs, "cwtof_depth").data[0], depth, 1e-3) << depth;
  }
  // One frequency alone cannot.
  const auto single = runCwTof(singleReturn(5.1, 200, 1000.0f), noiseFree({100e6}), 1);
  EXPECT_GT(std::fabs(output(single, "cwtof_depth").data[0] - 5.1), 1.0);
}

TEST(CwTofTest, SquareModulationReproducesTheHarmonicsError) {
  // Four steps on a triangle correlation: for true phase theta in [0, pi/2]
  // the estimate is atan2(2 theta / pi, 1 - 2 theta / pi).
  const double f = 20e6;
  double maxError = 0.0;
  for (double theta : {0.2, M_PI / 8, 0.6, 1.1, 1.4}) {
    const double depth = kC * theta / (4 * M_PI * f);
    CwTofParams p = noiseFree({f});
    p.waveform = Waveform::Square;
    const auto outs = runCwTof(singleReturn(depth, 200, 1000.0f), p, 1);
    const double estimate = std::atan2(2 * theta / M_PI, 1 - 2 * theta / M_PI);
    const double expected = kC * estimate / (4 * M_PI * f);
    EXPECT_NEAR(output(outs, "cwtof_depth").data[0], expected, 1e-3) << theta;
    maxError = std::max(maxError, std::fabs(expected - depth));
    p.waveform = Waveform::Sine;
    const auto sine = runCwTof(singleReturn(depth, 200, 1000.0f), p, 1);
    EXPECT_NEAR(output(sine, "cwtof_depth").data[0], depth, 1e-3) << theta;
  }
  EXPECT_GT(maxError, 0.05);  // the wiggling error is several centimetres at 20 MHz
}

TEST(CwTofTest, BinCorrelationIsTheExactBinAverage) {
  // Against a fine midpoint sum of the waveform over a wide bin.
  for (Waveform wf : {Waveform::Sine, Waveform::Square}) {
    const double f = 50e6, phi = 0.7, t0 = 3.1e-9, t1 = 9.4e-9;  // bin spans 0.3 periods
    double sum = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      const double t = t0 + (i + 0.5) * (t1 - t0) / n;
      const double th = 2 * M_PI * f * t - phi;
      const double u = th - 2 * M_PI * std::floor(th / (2 * M_PI));
      sum +=
          wf == Waveform::Sine ? std::cos(th) : (u <= M_PI ? 1 - 2 * u / M_PI : -3 + 2 * u / M_PI);
    }
    EXPECT_NEAR(binCorrelation(wf, f, phi, t0, t1), sum / n, 1e-8);
  }
}

TEST(CwTofTest, MultipathErrorAgainstGroundTruthAndDirectComponent) {
  const double w = 10e-12, f = 20e6;
  TransientVolume direct = makeVolume(2, 1, 0.0, w, 400);
  direct.at(0, 0, 200, 0) = 1000.0f;
  direct.at(0, 1, 200, 0) = 1000.0f;
  TransientVolume full = direct;
  full.at(0, 1, 300, 0) = 300.0f;  // pixel 1 has an indirect return
  Image truth(2, 1, 1);
  const double d = kC * 200.5 * w / 2;
  truth.at(0, 0, 0) = static_cast<float>(d);
  truth.at(0, 1, 0) = static_cast<float>(d);
  CwTofParams p;
  p.frequencies_Hz = {f};
  p.ambient_e = 200.0;  // noisy measurement; the MPI error is noise-free
  const auto outs = runCwTof(full, p, 3, CwTofReferences{&truth, &direct});
  const auto& gt = output(outs, "cwtof_mpi_error").data;
  const auto& dir = output(outs, "cwtof_mpi_error_direct").data;
  EXPECT_NEAR(gt[0], 0.0, 1e-4);
  EXPECT_NEAR(dir[0], 0.0, 1e-4);
  std::complex<double> sum = 1000.0 * std::polar(1.0, 2 * M_PI * f * 200.5 * w) +
                             300.0 * std::polar(1.0, 2 * M_PI * f * 300.5 * w);
  const double mpiDepth = kC * std::arg(sum) / (4 * M_PI * f);
  EXPECT_NEAR(gt[1], mpiDepth - d, 1e-4);
  EXPECT_NEAR(dir[1], mpiDepth - d, 1e-4);
  EXPECT_GT(gt[1], 0.02);  // the later, indirect light lengthens the depth (3.5 cm)
  EXPECT_EQ(test::array(outs, "cwtof_raw").shape, (std::vector<int64_t>{1, 4, 1, 2}));
}

// A fronto-parallel plane in water (eta = 1.33), seen by a camera with the
// light at it: each pixel's only return arrives after eta x the round trip.
// The depth is measured in the medium, so there is no multipath error, and
// with camera_unwarp (time at the surface: one leg) neither.
TEST(CwTofTest, PlaneInAMediumHasNoMultipathError) {
  const double eta = 1.33, w = 10e-12, f = 20e6, plane_m = 2.0;
  for (bool unwarp : {false, true}) {
    const int32_t W = 5, H = 3;
    TransientVolume v = makeVolume(W, H, 0.0, w, 2000);
    TimeAxis axis = v.axis();
    axis.index_of_refraction = eta;
    axis.camera_unwarp = unwarp;
    v = TransientVolume(W, H, axis, {"c0"});
    Image truth(W, H, 1);
    for (int32_t y = 0; y < H; ++y) {
      for (int32_t x = 0; x < W; ++x) {
        // Pixel rays fan out: distance to the plane grows off the centre.
        const double d = plane_m * std::hypot(1.0, 0.1 * (x - 2), 0.1 * (y - 1));
        const double t = (unwarp ? 1.0 : 2.0) * eta * d / kC;
        const int32_t bin = axis.binOf(t);
        ASSERT_GE(bin, 0);
        v.at(y, x, bin, 0) = 1000.0f;
        // The truth the bin's centre stands for (the sensor sees the bin, not t).
        truth.at(y, x, 0) = static_cast<float>(axis.depthOf_m(axis.binCenter_s(bin)));
        EXPECT_NEAR(truth.at(y, x, 0), d, 0.5 * w * kC / eta) << x << "," << y;
      }
    }
    CwTofParams p = noiseFree({f});
    const auto outs = runCwTof(v, p, 1, CwTofReferences{&truth, nullptr});
    for (float e : output(outs, "cwtof_mpi_error").data) EXPECT_NEAR(e, 0.0, 1e-4) << unwarp;
    // Depth in the medium: a vacuum reading would be 1.33 x 2 m = 2.66 m.
    EXPECT_NEAR(output(outs, "cwtof_depth").data[1 * W + 2], plane_m, 0.5 * w * kC / eta);
  }
}

TEST(CwTofTest, UnwrapRangeShrinksInAMedium) {
  TimeAxis water;
  water.index_of_refraction = 1.33;
  EXPECT_NEAR(unwrapRange_m(noiseFree({20e6}), water.depthPerSecond_m_per_s()),
              kC / 1.33 / (2 * 20e6), 1e-9);
}

TEST(CwTofTest, RawNoiseIsShotPlusReadAndReproducible) {
  TransientVolume v = makeVolume(64, 64, 0.0, 10e-12, 4);
  for (float& e : v.values()) e = 100.0f;  // 400 e- per pixel
  CwTofParams p;
  p.read_noise_e = 3.0;
  p.ambient_e = 100.0;
  const auto a = runCwTof(v, p, 8), b = runCwTof(v, p, 8);
  const auto& raw = test::array(a, "cwtof_raw").data;
  EXPECT_EQ(raw, test::array(b, "cwtof_raw").data);
  // Phase step 0 at 20 MHz: all bins within 40 ps of t = 0, correlation ~ 1.
  const int n = 64 * 64;
  double s = 0, s2 = 0, expect = 0;
  for (int t = 0; t < 4; ++t)
    expect += 0.5 * 100 * (1 + binCorrelation(Waveform::Sine, 20e6, 0, t * 1e-11, (t + 1) * 1e-11));
  expect += 0.5 * 100.0;
  for (int i = 0; i < n; ++i) {
    s += raw[i];
    s2 += static_cast<double>(raw[i]) * raw[i];
  }
  const double mean = s / n, var = (s2 - s * s / n) / (n - 1), ev = expect + 9.0;
  EXPECT_NEAR(mean, expect, 4.0 * std::sqrt(ev / n));
  EXPECT_NEAR(var, ev, 4.0 * std::sqrt(2.0 * ev * ev / n));
}

// A fronto-parallel plane at 2.2 m (every pixel's only return there) and its
// ground truth: beyond the 1.5 m unambiguous range of 100 MHz.
struct PlaneBeyondRange {
  TransientVolume volume = singleReturn(2.2, 200, 1000.0f);
  Image truth{1, 1, 1};
  PlaneBeyondRange() {
    // The truth the bin's centre stands for (the sensor sees the bin).
    truth.at(0, 0, 0) = static_cast<float>(volume.axis().depthOf_m(volume.axis().binCenter_s(100)));
  }
};

TEST(CwTofTest, OneFrequencyReportsAPhaseWrapAsAmbiguityNotMultipath) {
  const PlaneBeyondRange plane;
  const CwTofParams p = noiseFree({100e6});
  const double range = kC / (2 * 100e6);  // 1.499 m
  EXPECT_NEAR(depthRange_m(p, kC / 2), range, 1e-9);
  const auto outs = runCwTof(plane.volume, p, 1, CwTofReferences{&plane.truth, nullptr});
  const double truth = plane.truth.at(0, 0, 0);
  EXPECT_NEAR(output(outs, "cwtof_depth").data[0], truth - range, 1e-3);  // the wrapped depth
  EXPECT_NEAR(output(outs, "cwtof_depth_100MHz").data[0], truth - range, 1e-3);
  EXPECT_LT(std::fabs(output(outs, "cwtof_mpi_error").data[0]), 1e-3);  // not -1.5 m
  EXPECT_LT(std::fabs(output(outs, "cwtof_multipath_error_100MHz").data[0]), 1e-3);
  // Nothing was unwrapped, so no title says so.
  for (const SensorOutput& o : outs) {
    EXPECT_EQ(o.description.find("unwrapped"), std::string::npos) << o.name;
  }
  const std::vector<std::string> warnings = cwtofWarnings(p, plane.volume.axis(), &plane.truth);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("1.499 m unambiguous range of 100MHz"), std::string::npos)
      << warnings[0];
  // Within range, or without a truth, there is nothing to warn about.
  EXPECT_TRUE(cwtofWarnings(noiseFree({20e6}), plane.volume.axis(), &plane.truth).empty());
  EXPECT_TRUE(cwtofWarnings(p, plane.volume.axis(), nullptr).empty());
}

TEST(CwTofTest, TwoFrequenciesGiveTheUnwrappedAndEachWrappedDepth) {
  const PlaneBeyondRange plane;
  const CwTofParams p = noiseFree({80e6, 100e6});  // together 7.49 m
  const auto outs = runCwTof(plane.volume, p, 1, CwTofReferences{&plane.truth, nullptr});
  const double truth = plane.truth.at(0, 0, 0);
  EXPECT_NEAR(output(outs, "cwtof_depth").data[0], truth, 1e-3);
  EXPECT_NE(output(outs, "cwtof_depth", SensorOutput::Kind::ColorMappedImage)
                .description.find("unwrapped"),
            std::string::npos);
  EXPECT_LT(std::fabs(output(outs, "cwtof_mpi_error").data[0]), 1e-3);
  for (double f : {80e6, 100e6}) {
    const std::string label = frequencyLabel(f);
    const double range = kC / (2 * f);
    const double wrapped = truth - range * std::floor(truth / range);
    EXPECT_NEAR(output(outs, "cwtof_depth_" + label).data[0], wrapped, 1e-3) << label;
    EXPECT_NEAR(output(outs, "cwtof_phase_" + label).data[0], 2 * M_PI * wrapped / range, 1e-3);
    EXPECT_LT(std::fabs(output(outs, "cwtof_multipath_error_" + label).data[0]), 1e-3);
    EXPECT_GT(output(outs, "cwtof_amplitude_" + label).data[0], 400.0f);
    output(outs, "cwtof_depth_" + label, SensorOutput::Kind::ColorMappedImage);
  }
  EXPECT_EQ(frequencyLabel(80e6), "80MHz");
  EXPECT_EQ(frequencyLabel(12.5e6), "12.5MHz");
  EXPECT_TRUE(cwtofWarnings(p, plane.volume.axis(), &plane.truth).empty());
}

TEST(CwTofTest, FrequenciesWithTheSameOutputNameAreAnInputError) {
  EXPECT_THROW(runCwTof(singleReturn(1.0, 200, 1.0f), noiseFree({20e6, 20.0000001e6}), 1),
               InputError);
}

}  // namespace
}  // namespace tofsim::sensors
