// A SPAD's `irf:` read from a file by the config layer: .npy and CSV, paths
// relative to the config's folder, t0 and floor, and located errors for bad
// files (the config file's line, the key, the IRF file and its line).

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "ConfigNode.h"
#include "support/ShortNumber.h"
#include "support/TempDir.h"
#include "tofsim/config/SensorConfig.h"
#include "tofsim/io/Npy.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::config {
namespace {

using namespace tofsim::sensors;

constexpr double kSigma = 1e-12, kStep = 0.002e-12;

class SpadIrfConfigTest : public test::TempDirTest {
 protected:
  /// The spad sensor of a config file written as `name` in the test folder.
  SpadParams parse(const std::string& irfYaml, const std::string& name = "sensor.yaml") {
    const std::string text =
        "sensors:\n  - type: spad\n    pde: 1\n    ambient_rate: 1e9\n    irf: " + irfYaml + "\n";
    const std::filesystem::path file = dir_ / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
    const ConfigNode root(YAML::LoadFile(file.string()), file.string());
    const std::vector<SensorSpec> specs = parseSensors(root.child("sensors"));
    root.reportUnusedKeys();
    return std::get<SpadParams>(specs.front().params);
  }
  std::string errorOf(const std::string& irfYaml) {
    try {
      parse(irfYaml);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }

  // A Gaussian of sigma 1 ps sampled at 0.002 ps, each value its integral
  // over the sample, as `time,value` rows (17 digits) from -8 to 8 sigma.
  void writeGaussianCsv(const std::string& name) {
    std::ofstream out(dir_ / name);
    out << "time_s,value\n";
    const auto cdf = [](double t) { return 0.5 * std::erfc(-t / (kSigma * std::sqrt(2.0))); };
    const int half = static_cast<int>(std::lround(8.0 * kSigma / kStep));
    char line[96];
    for (int k = -half; k <= half; ++k) {
      std::snprintf(line, sizeof line, "%.17g,%.17g\n", k * kStep,
                    cdf((k + 0.5) * kStep) - cdf((k - 0.5) * kStep));
      out << line;
    }
  }
};

// First-photon probabilities of one pixel: a sharp return and a weak one.
std::vector<double> firstPhoton(const SpadParams& p) {
  TimeAxis axis;
  axis.bin_width_s = 4e-12;
  axis.bins = 64;
  TransientVolume v(1, 1, axis, {"c0"});
  v.at(0, 0, 20, 0) = 0.8f;
  v.at(0, 0, 21, 0) = 0.3f;
  v.at(0, 0, 40, 0) = 0.05f;
  std::vector<double> f;
  spadFluxPerCycle(v, p, resolveBins(p.bins, v.axis()), 0, 0, f);
  return firstPhotonProbabilities(f);
}

double maxAbsDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::fabs(a[i] - b[i]));
  return d;
}

using tofsim::test::sci;

TEST_F(SpadIrfConfigTest, GaussianIrfFilesReproduceTheJitterModel) {
  SpadParams jitter;
  jitter.pde = 1.0;
  jitter.ambient_rate_per_s = 1e9;
  jitter.jitter_fwhm_s = kSigma * 2.0 * std::sqrt(2.0 * std::log(2.0));
  const std::vector<double> expected = firstPhoton(jitter);

  writeGaussianCsv("gauss.csv");
  const SpadParams csv = parse("{file: gauss.csv, t0: 0 s}");
  EXPECT_NEAR(csv.irf.sample_width_s, kStep, 1e-9 * kStep);
  const double dCsv = maxAbsDifference(firstPhoton(csv), expected);
  RecordProperty("csv_max_abs_difference", sci(dCsv));
  EXPECT_LT(dCsv, 1e-6);

  // The same values as a float32 .npy, sample k at k bin_width: its centre
  // (index `half`) is zero delay, also found by t0: centroid.
  std::vector<float> values;
  for (double v : csv.irf.values) values.push_back(static_cast<float>(v));
  io::writeNpy(dir_ / "gauss.npy", {values.size()}, values.data());
  const SpadParams npy = parse("{file: gauss.npy, bin_width: 0.002 ps, t0: centroid}");
  const double dNpy = maxAbsDifference(firstPhoton(npy), expected);
  RecordProperty("npy_max_abs_difference", sci(dNpy));
  EXPECT_LT(dNpy, 1e-6);
  // The file's time zero off by half a bin is seen.
  const SpadParams shifted = parse("{file: gauss.csv, t0: 2 ps}");
  EXPECT_GT(maxAbsDifference(firstPhoton(shifted), expected), 1e-3);
}

TEST_F(SpadIrfConfigTest, RelativePathsFloorAndTimeZeroRoundTrip) {
  write("irf.csv", "# measured\n0,1\n1e-12,5\n2e-12,3\n3e-12,1.5\n");
  const SpadParams p = parse("{file: ../irf.csv, t0: centroid, floor: 1.2}", "sub/sensor.yaml");
  EXPECT_EQ(p.irf.file, (dir_ / "irf.csv").lexically_normal().string());
  EXPECT_EQ(p.irf.values, (std::vector<double>{0.0, 5 - 1.2, 3 - 1.2, 1.5 - 1.2}));
  EXPECT_DOUBLE_EQ(p.irf.first_time_s, 0.0);
  EXPECT_DOUBLE_EQ(p.irf.sample_width_s, 1e-12);
  EXPECT_EQ(p.irf.t0, SpadIrf::TimeZero::Centroid);
  EXPECT_EQ(parse("{file: irf.csv}").irf.t0, SpadIrf::TimeZero::Peak);
  const SpadParams at = parse("{file: irf.csv, t0: 2.5 ps}");  // within [-0.5, 3.5] ps
  EXPECT_EQ(at.irf.t0, SpadIrf::TimeZero::Time);
  EXPECT_DOUBLE_EQ(at.irf.t0_s, 2.5e-12);
  // The effective config reads back to the same response.
  SensorSpec spec;
  spec.params = p;
  YAML::Node doc;
  doc["sensors"] = sensorsToYaml({spec});
  const ConfigNode again(doc, (dir_ / "effective.yaml").string());
  const auto back = std::get<SpadParams>(parseSensors(again.child("sensors")).front().params);
  EXPECT_EQ(back.irf.values, p.irf.values);
  EXPECT_EQ(back.irf.file, p.irf.file);
  EXPECT_EQ(back.irf.t0, p.irf.t0);
  EXPECT_EQ(back.irf.floor, p.irf.floor);
}

TEST_F(SpadIrfConfigTest, BadFilesGiveLocatedErrors) {
  // The irf mapping is on line 5 of sensor.yaml; its `file` value at column 16.
  const std::string at = (dir_ / "sensor.yaml").string() + ":5:";
  const auto expectError = [&](const std::string& irf, const std::string& where,
                               const std::string& what) {
    const std::string e = errorOf(irf);
    SCOPED_TRACE(irf + " -> " + e);
    EXPECT_NE(e.find(at), std::string::npos);
    EXPECT_NE(e.find(where), std::string::npos);
    EXPECT_NE(e.find(what), std::string::npos);
  };
  const std::string file = "sensors[0].irf.file";
  expectError("{file: missing.csv}", file, "IRF file not found");
  write("three.csv", "t,v\n0,1\n1e-12,2,3\n");
  expectError("{file: three.csv}", file, "three.csv:3: expected 2 columns");
  write("negative.csv", "0,1\n1e-12,2\n2e-12,-0.5\n");
  expectError("{file: negative.csv}", file, "negative.csv:3: negative value -0.5");
  write("words.csv", "0,1\n1e-12,two\n");
  expectError("{file: words.csv}", file, "words.csv:2: expected 2 finite numbers");
  write("uneven.csv", "0,1\n1e-12,2\n3e-12,1\n");
  expectError("{file: uneven.csv}", file, "uneven.csv:3: times are not evenly spaced");
  write("flat.csv", "0,1\n1e-12,1\n");
  expectError("{file: flat.csv, floor: 1}", file, "no area above the floor");
  write("zero.csv", "0,0\n1e-12,0\n");
  expectError("{file: zero.csv}", file, "no area");
  expectError("{file: three.csv, bin_width: 1 ps}", "sensors[0].irf.bin_width", "time column");
  write("irf.txt", "0,1\n");
  expectError("{file: irf.txt}", file, ".npy or .csv");
  const std::vector<float> v2 = {1, 2, 3, 4};
  io::writeNpy(dir_ / "two_d.npy", {2, 2}, v2.data());
  expectError("{file: two_d.npy, bin_width: 1 ps}", file, "expected a 1-D array");
  const std::vector<float> neg = {1, -2, 3};
  io::writeNpy(dir_ / "neg.npy", {3}, neg.data());
  expectError("{file: neg.npy, bin_width: 1 ps}", file, "at index 1 is negative");
  expectError("{file: neg.npy}", file, "needs `bin_width`");
  write("junk.npy", "not an npy");
  expectError("{file: junk.npy, bin_width: 1 ps}", file, "junk.npy");
  write("ok.csv", "0,1\n1e-12,2\n");
  expectError("{file: ok.csv, t0: middle}", "sensors[0].irf.t0", "peak, centroid or a time");
  expectError("{file: ok.csv, floor: -1}", "sensors[0].irf.floor", ">= 0");
  expectError("{file: ok.csv, tail: 3}", "sensors[0].irf.tail", "");
  // With pulse or jitter given too.
  std::ofstream(dir_ / "jitter.yaml")
      << "sensors:\n  - type: spad\n    jitter_fwhm: 10 ps\n    irf: {file: ok.csv}\n";
  const ConfigNode root(YAML::LoadFile((dir_ / "jitter.yaml").string()),
                        (dir_ / "jitter.yaml").string());
  try {
    parseSensors(root.child("sensors"));
    ADD_FAILURE() << "jitter_fwhm with irf was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("jitter.yaml:3:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("`irf` replaces"), std::string::npos) << e.what();
  }
}

TEST_F(SpadIrfConfigTest, AHotPixelFractionNeedsARate) {
  std::ofstream(dir_ / "hot.yaml") << "sensors:\n  - type: spad\n    hot_pixel_fraction: 0.01\n";
  const ConfigNode root(YAML::LoadFile((dir_ / "hot.yaml").string()), (dir_ / "hot.yaml").string());
  EXPECT_THROW(parseSensors(root.child("sensors")), InputError);
}

}  // namespace
}  // namespace tofsim::config
