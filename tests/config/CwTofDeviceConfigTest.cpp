// The config side of the CW-ToF device stage: fixed-pattern maps, taps, the
// ADC and its companding curve, the capture order; the effective config's
// round trip and located errors (file:line:col, key) before anything is
// rendered.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include "ConfigNode.h"
#include "SensorKeysTest.h"
#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/config/SensorConfig.h"
#include "tofsim/io/Npy.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/util/Error.h"

namespace tofsim::config {
namespace {

// 32 x 24 pixels.
const char* kRun = R"(scene: scene.gltf
camera:
  position: [0, 0, 2]
  look_at: [0, 0, 0]
  fov_y: 45 deg
  resolution: [32, 24]
light:
  type: spot
  position: [0, 1, 2]
  direction: [0, 0, -1]
  cone_angle: 0.5 rad
  intensity: [1, 2, 3]
time:
  start: 1 ns
  bin_width: 10 ps
  bins: 100
sensors:
  - type: cwtof
    frequencies: [80 MHz, 16 MHz, 120 MHz]
    phase_steps: 3
)";

class CwTofDeviceConfigTest : public test::RunSensorKeysTest<sensors::CwTofParams> {
 protected:
  CwTofDeviceConfigTest() : RunSensorKeysTest(kRun) {}
  /// An error at test.yaml:<line>: naming the key and the words.
  void expectError(const std::string& keys, int line, const std::string& key,
                   const std::string& words) {
    const std::string message = errorOf(keys);
    EXPECT_NE(message.find("test.yaml:" + std::to_string(line) + ":"), std::string::npos)
        << message;
    EXPECT_NE(message.find("sensors[0]." + key), std::string::npos) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
  }
  void writeMap(const char* name, io::NpyShape shape, float value, int bad = -1,
                float badValue = 0.0f) {
    std::size_t n = 1;
    for (std::size_t d : shape) n *= d;
    std::vector<float> values(n, value);
    if (bad >= 0) values[bad] = badValue;
    io::writeNpy(dir_ / name, shape, values.data());
  }
};

constexpr int kFirstKeyLine = 21;  // the line after kRun

TEST_F(CwTofDeviceConfigTest, ReadsEveryDeviceKeyAndRoundTrips) {
  writeMap("delay.npy", {24, 32}, -2e-11f);
  writeMap("gain.npy", {24, 32}, 1.1f);
  writeMap("offset.npy", {24, 32}, -3.0f);
  std::ofstream(dir_ / "compand.csv") << "input_dn,output_dn\n0,0\n1024,1024\n4096,2048\n";
  const sensors::CwTofParams p = load(
      "    fpn_seed: 9\n    delay_map: delay.npy\n    gain_map: gain.npy\n"
      "    offset_map: offset.npy\n    taps: 2\n    tap_a_gain: 1.02\n    tap_b_gain: 0.98\n"
      "    output_taps: true\n    ambient_suppression: 0.5\n    dark_current: 3\n"
      "    full_well: 30000\n    adc_bits: 12\n    adc_gain: 0.25\n    adc_offset: 2048\n"
      "    companding: compand.csv\n"
      "    capture_order: [[0, 0], [0, 1], [0, 2], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], "
      "[2, 2]]\n    integration_time: 100 us\n    readout_gap: 20 us\n");
  EXPECT_EQ(p.delay_map.height, 24);
  EXPECT_FLOAT_EQ(static_cast<float>(p.delay_map.values[7]), -2e-11f);
  EXPECT_EQ(p.taps, 2);
  EXPECT_EQ(p.adc_bits, 12);
  EXPECT_EQ(p.companding.output_dn, (std::vector<double>{0, 1024, 2048}));
  EXPECT_EQ(p.capture_order.size(), 9u);
  EXPECT_DOUBLE_EQ(p.integration_time_s, 100e-6);
  EXPECT_DOUBLE_EQ(sensors::cwtofRawStartTimes_s(p)[8], 8 * 120e-6);
  // The effective config reads back as the same device.
  YAML::Node doc;
  doc["sensors"] = sensorsToYaml({sensors::SensorSpec{"cwtof", p}});
  const ConfigNode again(YAML::Load(YAML::Dump(doc)), "effective.yaml");
  const std::vector<sensors::SensorSpec> specs = parseSensors(again.child("sensors"));
  const auto& q = std::get<sensors::CwTofParams>(specs[0].params);
  EXPECT_EQ(q.delay_map.values, p.delay_map.values);
  EXPECT_EQ(q.offset_map.file, p.offset_map.file);
  EXPECT_EQ(q.companding.input_dn, p.companding.input_dn);
  EXPECT_EQ(q.capture_order, p.capture_order);
  EXPECT_EQ(q.fpn_seed, 9);
  EXPECT_DOUBLE_EQ(q.ambient_suppression, 0.5);
  EXPECT_DOUBLE_EQ(q.adc_offset_dn, 2048.0);
  EXPECT_DOUBLE_EQ(q.readout_gap_s, 20e-6);
  // An inline companding list too.
  const sensors::CwTofParams inl =
      load("    adc_bits: 10\n    companding: [[0, 0], [100, 50], [1000, 500]]\n");
  EXPECT_EQ(inl.companding.input_dn, (std::vector<double>{0, 100, 1000}));
}

TEST_F(CwTofDeviceConfigTest, NoiseTableReadsAndChecks) {
  std::ofstream(dir_ / "noise.csv") << "mean,sample\n# two means\n10,9\n10,12\n12,11.5\n";
  const sensors::CwTofParams p = load("    noise_model: table\n    noise_table: noise.csv\n");
  EXPECT_EQ(p.noise_model, sensors::CwTofNoiseModel::Table);
  EXPECT_EQ(p.noise_table.first_mean_e, 10);
  ASSERT_EQ(p.noise_table.samples.size(), 3u);
  EXPECT_EQ(p.noise_table.samples[0], (std::vector<double>{9, 12}));
  EXPECT_TRUE(p.noise_table.samples[1].empty());
  EXPECT_EQ(p.noise_table.at(11.6), &p.noise_table.samples[2]);
  YAML::Node doc;
  doc["sensors"] = sensorsToYaml({sensors::SensorSpec{"cwtof", p}});
  const ConfigNode again(YAML::Load(YAML::Dump(doc)), "effective.yaml");
  const std::vector<sensors::SensorSpec> specs = parseSensors(again.child("sensors"));
  EXPECT_EQ(std::get<sensors::CwTofParams>(specs[0].params).noise_table.samples,
            p.noise_table.samples);
  std::ofstream(dir_ / "half.csv") << "10,9\n10.5,12\n";
  {
    const std::string message = errorOf("    noise_model: table\n    noise_table: half.csv\n");
    EXPECT_NE(message.find((dir_ / "half.csv").string() + ":2"), std::string::npos) << message;
    EXPECT_NE(message.find("is not an integer"), std::string::npos) << message;
  }
  expectError("    noise_model: table\n", kFirstKeyLine, "noise_model", "needs `noise_table`");
  expectError("    noise_table: noise.csv\n", kFirstKeyLine, "noise_table",
              "is for `noise_model: table`");
  expectError("    noise_model: table\n    noise_table: noise.csv\n    read_noise: 2\n",
              kFirstKeyLine + 2, "read_noise", "holds the read noise");
}

TEST_F(CwTofDeviceConfigTest, BadMapsAreLocatedErrors) {
  writeMap("narrow.npy", {24, 31}, 1.0f);
  expectError("    gain_map: narrow.npy\n", kFirstKeyLine, "gain_map",
              "24 x 31 (H x W) but the image is 24 x 32");
  writeMap("nan.npy", {24, 32}, 0.0f, 40, std::numeric_limits<float>::quiet_NaN());
  expectError("    offset_map: nan.npy\n", kFirstKeyLine, "offset_map",
              "(y, x) = (1, 8) is not finite");
  writeMap("negative.npy", {24, 32}, 1.0f, 3, -0.5f);
  expectError("    gain_map: negative.npy\n", kFirstKeyLine, "gain_map", "is negative");
  writeMap("flat.npy", {24 * 32}, 1.0f);
  expectError("    delay_map: flat.npy\n", kFirstKeyLine, "delay_map", "expected a 2-D array");
  writeMap("delay.npy", {24, 32}, 1e-11f);
  expectError("    delay_map: delay.npy\n    delay_sigma: 10 ps\n", kFirstKeyLine + 1,
              "delay_sigma", "replaces the draw");
}

TEST_F(CwTofDeviceConfigTest, BadAdcTapsAndOrderAreLocatedErrors) {
  expectError("    adc_bits: 25\n", kFirstKeyLine, "adc_bits", "must be in [0, 24] (got 25)");
  expectError("    taps: 3\n", kFirstKeyLine, "taps", "must be in [1, 2]");
  expectError("    ambient_suppression: 0.5\n", kFirstKeyLine, "ambient_suppression", "`taps: 2`");
  expectError("    adc_gain: 2\n", kFirstKeyLine, "adc_gain", "needs `adc_bits`");
  expectError("    adc_bits: 12\n    companding: [[0, 0], [100, 50], [90, 60]]\n",
              kFirstKeyLine + 1, "companding", "point 2: inputs must increase (90 after 100)");
  expectError("    adc_bits: 12\n    companding: [[0, 10], [100, 5]]\n", kFirstKeyLine + 1,
              "companding", "outputs must not decrease");
  std::ofstream(dir_ / "down.csv") << "0,0\n10,5\n20,4\n";
  {
    const std::string message = errorOf("    adc_bits: 12\n    companding: down.csv\n");
    EXPECT_NE(message.find((dir_ / "down.csv").string() + ":3"), std::string::npos) << message;
    EXPECT_NE(message.find("outputs must not decrease"), std::string::npos) << message;
  }
  expectError("    capture_order: [[0, 0], [3, 1]]\n", kFirstKeyLine, "capture_order",
              "is not a (frequency index, phase step) of 3 frequencies x 3 steps");
  expectError("    capture_order: [[0, 0], [0, 0]]\n", kFirstKeyLine, "capture_order",
              "listed twice");
  expectError("    capture_order: [[0, 0], [0, 1]]\n", kFirstKeyLine, "capture_order",
              "lists 2 raws of 9");
}

}  // namespace
}  // namespace tofsim::config
