// CW-ToF device presets (CwTofPresets.h) on synthetic volumes: every preset
// runs and measures the depth of a known single return; the kinect-v2
// preset's 9 raws in capture order, decoded with libfreenect2's own phase
// formulas, give tofsim's phases; and an image that is not the device's
// array is a warning.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "TestVolumes.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/sensors/CwTofPresets.h"
#include "tofsim/sensors/RunSensor.h"

namespace tofsim::sensors {
namespace {

using test::array;
using test::makeVolume;
using test::output;

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kBin_s = 20e-12;

/// The preset's parameters with every noise off.
CwTofParams noiseFree(const char* name) {
  const CwTofPreset* preset = findCwTofPreset(name);
  EXPECT_NE(preset, nullptr) << name;
  CwTofParams p;
  preset->apply(p);
  p.preset = name;
  p.shot_noise = false;
  return p;
}

/// W x H pixels, pixel i one delta of `energy` in bin firstBin + i * step.
TransientVolume deltas(int32_t W, int32_t H, int32_t firstBin, int32_t step, float energy) {
  TransientVolume v = makeVolume(W, H, 0.0, kBin_s, firstBin + W * H * step + 1);
  for (int32_t i = 0; i < W * H; ++i) v.at(i / W, i % W, firstBin + i * step, 0) = energy;
  return v;
}

/// The delay of pixel i's return: its bin's centre (the bin average of a
/// sine has the phase of the centre exactly).
double delay_s(int32_t firstBin, int32_t step, int32_t i) {
  return (firstBin + i * step + 0.5) * kBin_s;
}

/// libfreenect2's processMeasurementTriple, written out: raws m_0..m_2 of one
/// frequency in its order, theta_k = 0, 2.094395, 4.18879 rad (p0 = 0):
/// ir_a = sum cos(theta_k) m_k, ir_b = sum sin(-theta_k) m_k, phase =
/// atan2(ir_b, ir_a) wrapped to [0, 2 pi).
double libfreenect2Phase(const double m[3]) {
  const double theta[3] = {0.0, 2.094395, 4.18879};
  double a = 0.0, b = 0.0;
  for (int k = 0; k < 3; ++k) {
    a += std::cos(theta[k]) * m[k];
    b += std::sin(-theta[k]) * m[k];
  }
  double phase = std::atan2(b, a);
  if (phase < 0.0) phase += kTwoPi;
  return phase;
}

/// |a - b| on the circle.
double angleBetween(double a, double b) { return std::fabs(std::remainder(a - b, kTwoPi)); }

TEST(CwTofPresetTest, EveryPresetMeasuresTheDepthOfASingleReturn) {
  const int32_t W = 4, H = 3, first = 40, step = 25;  // 0.12 .. 0.95 m
  const TransientVolume v = deltas(W, H, first, step, 1000.0f);
  const double k = v.axis().depthPerSecond_m_per_s();
  for (const CwTofPreset& preset : cwtofPresets()) {
    SCOPED_TRACE(preset.name);
    const CwTofParams p = noiseFree(preset.name);
    ASSERT_LT(k * delay_s(first, step, W * H - 1), depthRange_m(p, k));
    const std::vector<SensorOutput> outs = runCwTof(v, p, 7);
    const SensorOutput& depth = output(outs, "cwtof_depth");
    for (int32_t i = 0; i < W * H; ++i) {
      // The f^2-weighted mean of per-frequency depths of the centre's phase.
      EXPECT_NEAR(depth.data[i], k * delay_s(first, step, i), 1e-4) << "pixel " << i;
    }
    // A preset with an ADC measures it from the DN raws too.
    if (p.adc_bits > 0) {
      const SensorOutput& device = output(outs, "cwtof_device_depth");
      for (int32_t i = 0; i < W * H; ++i) {
        EXPECT_NEAR(device.data[i], k * delay_s(first, step, i), 2e-3) << "pixel " << i;
      }
    }
  }
}

TEST(CwTofPresetTest, KinectV2RawsDecodedAsLibfreenect2GiveTofsimsPhases) {
  const int32_t W = 5, H = 4, first = 30, step = 97;  // delays 0.61 .. 37.5 ns
  const TransientVolume v = deltas(W, H, first, step, 4000.0f);
  const CwTofParams p = noiseFree("kinect-v2");
  ASSERT_EQ(p.frequencies_Hz, (std::vector<double>{80e6, 16e6, 120e6}));
  const std::vector<SensorOutput> outs = runCwTof(v, p, 3);
  const std::size_t HW = static_cast<std::size_t>(W) * H;
  const std::vector<float>& raw = array(outs, "cwtof_raw").data;      // (F, N, H, W) e-
  const SensorOutput& sequence = array(outs, "cwtof_raw_sequence");   // (9, H, W) DN
  const std::vector<float>& phase = array(outs, "cwtof_phase").data;  // (F, H, W)
  const std::vector<float>& devicePhase = array(outs, "cwtof_device_phase").data;
  ASSERT_EQ(sequence.shape, (std::vector<int64_t>{9, H, W}));
  const std::vector<CwTofCaptureStep> order = cwtofCaptureOrder(p);
  ASSERT_EQ(order.size(), 9u);
  // The float raws in capture order, and the same in the (F, N) order a
  // decoder would wrongly take for libfreenect2's.
  const auto captured = [&](std::size_t i, std::size_t px, bool asCaptured) {
    const CwTofCaptureStep s =
        asCaptured ? order[i] : CwTofCaptureStep{int32_t(i / 3), int32_t(i % 3)};
    return double(raw[(static_cast<std::size_t>(s.frequency) * 3 + s.step) * HW + px]);
  };
  double worstFloat = 0.0, worstDn = 0.0, worstWrongOrder = 0.0, worstTruth = 0.0;
  for (std::size_t px = 0; px < HW; ++px) {
    for (std::size_t f = 0; f < 3; ++f) {
      // Sub-images 3f .. 3f + 2 are frequency f's (libfreenect2's layout).
      double m[3], dn[3], wrong[3];
      for (std::size_t k = 0; k < 3; ++k) {
        m[k] = captured(3 * f + k, px, true);
        wrong[k] = captured(3 * f + k, px, false);
        dn[k] = double(sequence.data[(3 * f + k) * HW + px]) - 32768.0;  // libfreenect2's int16
      }
      const double tofsim = phase[f * HW + px];
      worstFloat = std::max(worstFloat, angleBetween(libfreenect2Phase(m), tofsim));
      worstDn = std::max(worstDn, angleBetween(libfreenect2Phase(dn), devicePhase[f * HW + px]));
      worstWrongOrder = std::max(worstWrongOrder, angleBetween(libfreenect2Phase(wrong), tofsim));
      // And the phase of the return itself, 2 pi f tau of the bin's centre.
      const double truth = std::fmod(
          kTwoPi * p.frequencies_Hz[f] * delay_s(first, step, static_cast<int32_t>(px)), kTwoPi);
      worstTruth = std::max(worstTruth, angleBetween(libfreenect2Phase(m), truth));
    }
  }
  std::printf(
      "kinect-v2: max |libfreenect2 - tofsim| %.3g rad (float raws), %.3g rad (DN raws "
      "vs device phase), %.3g rad from the true phase; frequency-major order: %.3g rad\n",
      worstFloat, worstDn, worstTruth, worstWrongOrder);
  EXPECT_LT(worstFloat, 1e-6);
  EXPECT_LT(worstDn, 1e-6);
  EXPECT_LT(worstTruth, 1e-6);
  // Raws read in tofsim's step order decode to -phi: the capture order matters.
  EXPECT_GT(worstWrongOrder, 0.5);
}

TEST(CwTofPresetTest, KinectV2DnRawsAreInt16WithSaturationAt32767) {
  const TransientVolume v = deltas(2, 1, 100, 200, 1e6f);  // far past the int16 range
  CwTofParams p = noiseFree("kinect-v2");
  const std::vector<SensorOutput> outs = runCwTof(v, p, 3);
  const std::vector<float>& dn = array(outs, "cwtof_raw_sequence").data;
  double lo = 1e9, hi = -1e9;
  for (float x : dn) {
    lo = std::min(lo, x - 32768.0);
    hi = std::max(hi, x - 32768.0);
  }
  EXPECT_EQ(hi, 32767.0);   // libfreenect2's saturation mark
  EXPECT_EQ(lo, -32768.0);  // int16's other end
  for (float s : output(outs, "cwtof_saturated").data) EXPECT_EQ(s, 1.0f);
  for (float d : output(outs, "cwtof_device_depth").data) EXPECT_TRUE(std::isnan(d));
}

TEST(CwTofPresetTest, AnImageThatIsNotTheDevicesArrayIsAWarning) {
  const SensorSpec kinect{"k", noiseFree("kinect-v2")};
  VolumeShape shape{512, 424, 1, {}};
  shape.axis.bin_width_s = kBin_s;
  shape.axis.bins = 10;
  EXPECT_TRUE(sensorWarnings(kinect, shape, nullptr).empty());
  shape.width = 64;
  shape.height = 48;
  const std::vector<std::string> warnings = sensorWarnings(kinect, shape, nullptr);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("64 x 48"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("512 x 424"), std::string::npos) << warnings[0];
  // Without a preset, or with one of no fixed array, no warning.
  EXPECT_TRUE(sensorWarnings(SensorSpec{"c", CwTofParams{}}, shape, nullptr).empty());
  EXPECT_TRUE(sensorWarnings(SensorSpec{"p", noiseFree("pmd-generic")}, shape, nullptr).empty());
}

}  // namespace
}  // namespace tofsim::sensors
