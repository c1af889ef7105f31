// A CW-ToF sensor's measured `correlation:` read by the config layer: inline
// harmonics and samples, .csv and .npy files relative to the config's folder,
// one waveform per frequency, the effective config's round trip, and located
// errors (the config file's line, the key, the waveform file and its line).

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "ConfigNode.h"
#include "SensorKeysTest.h"
#include "support/TempDir.h"
#include "tofsim/config/SensorConfig.h"
#include "tofsim/io/Npy.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/sensors/CwTofWaveform.h"

namespace tofsim::config {
namespace {

using namespace tofsim::sensors;

class CwTofWaveformConfigTest : public test::SensorKeysTest<CwTofParams> {
 protected:
  CwTofWaveformConfigTest() : SensorKeysTest("cwtof") {}
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  /// Expects an error naming "sensor.yaml:<line>:", the key and the words.
  void expectError(const std::string& keys, int line, const std::string& key,
                   const std::string& words) {
    const std::string message = errorOf(keys);
    EXPECT_NE(message.find("sensor.yaml:" + std::to_string(line) + ":"), std::string::npos)
        << keys << " -> " << message;
    EXPECT_NE(message.find(key + ": "), std::string::npos) << keys << " -> " << message;
    EXPECT_NE(message.find(words), std::string::npos) << keys << " -> " << message;
  }
};

TEST_F(CwTofWaveformConfigTest, ReadsInlineFormsAndRoundTrips) {
  const CwTofParams p = parse(
      "    frequencies: [20 MHz, 50 MHz]\n    waveform: measured\n"
      "    modulation_contrast: 0.75\n"
      "    correlation:\n      - {harmonics: [[1, 0], [0, 0], [0.1, -0.05]]}\n"
      "      - {samples: [1, 0.25, -1, 0.25]}\n");
  EXPECT_EQ(p.waveform, Waveform::Measured);
  EXPECT_DOUBLE_EQ(p.modulation_contrast, 0.75);
  ASSERT_EQ(p.correlation.size(), 2u);
  EXPECT_EQ(p.correlation[0].harmonics[2], std::complex<double>(0.1, -0.05));
  EXPECT_EQ(p.correlation[1].values, (std::vector<double>{1, 0.25, -1, 0.25}));
  EXPECT_DOUBLE_EQ(p.correlation[1].phases_rad[1], M_PI / 2);  // 2 pi j / M
  // The effective config reads back as the same waveforms.
  YAML::Node doc;
  doc["sensors"] = sensorsToYaml({SensorSpec{"cwtof", p}});
  const ConfigNode again(YAML::Load(YAML::Dump(doc)), "effective.yaml");
  const std::vector<SensorSpec> specs = parseSensors(again.child("sensors"));
  const auto& q = std::get<CwTofParams>(specs.front().params);
  ASSERT_EQ(q.correlation.size(), 2u);
  ASSERT_EQ(q.correlation[0].harmonics.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {  // (gtest cannot print std::complex here)
    EXPECT_TRUE(q.correlation[0].harmonics[k] == p.correlation[0].harmonics[k]) << k;
  }
  EXPECT_EQ(q.correlation[1].values, p.correlation[1].values);
  EXPECT_DOUBLE_EQ(q.modulation_contrast, 0.75);
}

TEST_F(CwTofWaveformConfigTest, ReadsCsvAndNpyFiles) {
  // A header, a comment, uneven phases, and the period's closing row (dropped).
  write("corr.csv",
        "phase_rad,value\n# a triangle\n0,1\n1.5707963267948966,0\n3.14159265358979,-1\n"
        "6.283185307179586,1\n");
  const CwTofParams p = parse("    waveform: measured\n    correlation: {file: corr.csv}\n");
  ASSERT_EQ(p.correlation.size(), 1u);
  EXPECT_EQ(p.correlation[0].values, (std::vector<double>{1, 0, -1}));
  EXPECT_EQ(p.correlation[0].file, (dir_ / "corr.csv").string());
  // The triangle: its wiggling at N = 4 is the built-in square's.
  CwTofParams square;
  square.waveform = Waveform::Square;
  const auto a = wigglingError_m(p, 1.5e8), b = wigglingError_m(square, 1.5e8);
  for (std::size_t j = 0; j < a.size(); ++j) EXPECT_NEAR(a[j], b[j], 1e-9);

  const std::vector<float> samples = {0.0f, 1.0f, 0.0f, -1.0f};
  io::writeNpy(dir_ / "corr.npy", io::NpyShape{4}, samples.data());
  const CwTofParams q = parse("    waveform: measured\n    correlation: {file: corr.npy}\n");
  EXPECT_EQ(q.correlation[0].values, (std::vector<double>{0, 1, 0, -1}));
  EXPECT_DOUBLE_EQ(q.correlation[0].phases_rad[3], 1.5 * M_PI);
}

TEST_F(CwTofWaveformConfigTest, BadWaveformsAreLocatedErrors) {
  const std::string measured = "    waveform: measured\n";
  // Zero energy: no AC part, so no phase.
  expectError(measured + "    correlation: {harmonics: [[0, 0], [0, 0]]}\n", 4,
              "sensors[0].correlation.harmonics", "zero energy");
  write("flat.csv", "0,2\n1,2\n2,2\n");
  {
    const std::string message = errorOf(measured + "    correlation: {file: flat.csv}\n");
    EXPECT_NE(message.find("sensors[0].correlation.file: " + (dir_ / "flat.csv").string()),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("zero energy"), std::string::npos) << message;
  }
  // Wrong length: a list of waveforms that does not match `frequencies`.
  expectError("    frequencies: [20 MHz, 50 MHz, 80 MHz]\n" + measured +
                  "    correlation: [{samples: [1, -1]}, {samples: [1, 0, -1]}]\n",
              5, "sensors[0].correlation", "lists 2 waveforms for 3 frequencies");
  // NaN, inline and in a file (its line).
  expectError(measured + "    correlation: {samples: [1, nan, -1]}\n", 4,
              "sensors[0].correlation.samples[1]", "finite number");
  write("nan.csv", "0,1\n2,nan\n4,-1\n");
  {
    const std::string message = errorOf(measured + "    correlation: {file: nan.csv}\n");
    EXPECT_NE(message.find((dir_ / "nan.csv").string() + ":2: expected 2 finite numbers"),
              std::string::npos)
        << message;
  }
  // Not periodic: the row at 2 pi must repeat phase 0's value.
  write("open.csv", "phase_rad,value\n0,1\n3.14159,-1\n6.283185307179586,0.5\n");
  {
    const std::string message = errorOf(measured + "    correlation: {file: open.csv}\n");
    EXPECT_NE(message.find((dir_ / "open.csv").string() + ":4: not periodic"), std::string::npos)
        << message;
    EXPECT_NE(message.find("sensor.yaml:4:"), std::string::npos) << message;
  }
  write("back.csv", "0,1\n3,0\n2,-1\n");
  EXPECT_NE(
      errorOf(measured + "    correlation: {file: back.csv}\n").find(":3: phases must increase"),
      std::string::npos);
  expectError(measured + "    correlation: {file: missing.csv}\n", 4, "sensors[0].correlation.file",
              "file not found");
  expectError(measured + "    correlation: {samples: [1, -1], harmonics: [[1, 0]]}\n", 4,
              "sensors[0].correlation", "exactly one of");
  // The waveform and its key go together.
  expectError("    correlation: {samples: [1, -1]}\n", 3, "sensors[0].correlation",
              "waveform: measured");
  expectError(measured, 3, "sensors[0].waveform", "needs `correlation`");
  expectError("    modulation_contrast: 0\n", 3, "sensors[0].modulation_contrast", "(0, 1]");
}

// The stated caps (CwTofWaveform.h): one past them is a located error, and a
// waveform at the harmonics' cap loads (its scale found in O(K log K): the
// grid search was O(K^2), minutes at 20000 harmonics), its maximum right.
TEST_F(CwTofWaveformConfigTest, HarmonicsAndSamplesAreCappedAndTheCapLoads) {
  const std::string measured = "    waveform: measured\n";
  const auto harmonics = [](std::size_t K) {
    std::string list;
    char pair[64];
    for (std::size_t k = 1; k <= K; ++k) {
      std::snprintf(pair, sizeof pair, "%s[%.17g, 0]", k > 1 ? ", " : "", 1.0 / double(k * k));
      list += pair;
    }
    return "    correlation: {harmonics: [" + list + "]}\n";
  };
  expectError(measured + harmonics(kMaxHarmonics + 1), 4, "sensors[0].correlation.harmonics",
              "at most 4096");
  const CwTofParams p = parse(measured + harmonics(kMaxHarmonics));
  ASSERT_EQ(p.correlation[0].harmonics.size(), kMaxHarmonics);
  // sum c_k cos(k theta) with c_k > 0 peaks at theta = 0: max = sum c_k.
  double sum = 0.0;
  for (const auto& c : p.correlation[0].harmonics) sum += c.real();
  EXPECT_NEAR(PhaseCorrelation(p.correlation[0]).scale(), sum, 1e-12);

  std::vector<float> samples(kMaxSamples + 1);
  for (std::size_t j = 0; j < samples.size(); ++j) samples[j] = float(std::cos(0.001 * double(j)));
  io::writeNpy(dir_ / "long.npy", io::NpyShape{samples.size()}, samples.data());
  expectError(measured + "    correlation: {file: long.npy}\n", 4, "sensors[0].correlation.file",
              "at most 65536");
  io::writeNpy(dir_ / "cap.npy", io::NpyShape{kMaxSamples}, samples.data());
  EXPECT_EQ(parse(measured + "    correlation: {file: cap.npy}\n").correlation[0].values.size(),
            kMaxSamples);
}

}  // namespace
}  // namespace tofsim::config
