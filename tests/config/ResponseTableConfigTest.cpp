// A measured scattering-delay kernel read by the config layer (issue 41's
// `scattering_delay: {model: table, file, delay_unit}`,
// apps/config/src/ResponseTableFile): a table that samples an exponential
// gives the stage's bin integrals of that exponential (.csv in s, .npy in
// ns); bad tables are errors located at the config's key naming the file,
// its line or row and the column; a link is not read through.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "ConfigNode.h"
#include "ResponseTableFile.h"
#include "support/TempDir.h"
#include "tofsim/io/Npy.h"

namespace tofsim::config {
namespace {

class ResponseTableConfigTest : public test::TempDirTest {
 protected:
  physics::ResponseKernel parse(const std::string& mapping) {
    const std::filesystem::path file = dir_ / "materials.yaml";
    std::ofstream(file) << "materials:\n  wax:\n    scattering_delay: " << mapping << "\n";
    const ConfigNode root(YAML::LoadFile(file.string()), file.string());
    return parseResponseTable(root.child("materials").child("wax").child("scattering_delay"));
  }
  std::string errorOf(const std::string& mapping) {
    try {
      parse(mapping);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
};

constexpr double kTau_s = 2.5e-9, kBin_s = 10e-12;

// The exponential's bin integrals as the stage lays them out: tap 0, then
// the tail's tailWeight ratio^(m - 1).
std::vector<double> exponentialIntegrals(int count) {
  physics::ResponseKernel e;
  e.lifetime_s = kTau_s;
  const physics::ResponseTaps r = physics::responseTaps(e, kBin_s);
  std::vector<double> out = {r.taps[0]};
  for (int m = 1; m < count; ++m) out.push_back(r.tailWeight * std::pow(r.tailRatio, m - 1));
  return out;
}

void expectExponential(const physics::ResponseKernel& k) {
  ASSERT_EQ(k.model, physics::ResponseModel::Table);
  const physics::ResponseTaps r = physics::responseTaps(k, kBin_s);
  EXPECT_EQ(r.delay, 0);
  EXPECT_EQ(r.prompt, 0.0);
  const std::vector<double> want = exponentialIntegrals(2000);
  ASSERT_GE(r.taps.size(), want.size());
  double worst = 0.0;
  for (std::size_t m = 0; m < want.size(); ++m) {
    worst = std::max(worst, std::fabs(r.taps[m] - want[m]) / want[0]);
  }
  // Sampled every 2 ps to 30 tau: piecewise linear to (2 ps)^2 / (8 tau^2).
  EXPECT_LT(worst, 2e-5);
}

TEST_F(ResponseTableConfigTest, AnExponentialTableGivesTheExponentialsBinIntegrals) {
  std::ofstream csv(dir_ / "kernel.csv");
  csv << "# a fluorophore's decay, sampled\ndelay_s,weight\n";
  std::vector<float> rows;
  const double step = 2e-12;
  for (int i = 0; i * step <= 30 * kTau_s; ++i) {
    const double t = i * step, w = std::exp(-t / kTau_s);
    csv << t << "," << w << "\n";
    rows.push_back(static_cast<float>(t * 1e9));  // ns in the .npy
    rows.push_back(static_cast<float>(w));
  }
  csv.close();
  expectExponential(parse("{model: table, file: kernel.csv}"));
  io::writeNpy(dir_ / "kernel.npy", {rows.size() / 2, 2}, rows.data());
  expectExponential(parse("{model: table, file: kernel.npy, delay_unit: ns}"));
  // The wrong unit is a different kernel: 1000 times longer in ps.
  const physics::ResponseKernel ps = parse("{model: table, file: kernel.npy, delay_unit: ps}");
  EXPECT_NEAR(ps.tableDelay_s.back(), 30 * kTau_s * 1e-3, 1e-15);
}

TEST_F(ResponseTableConfigTest, BadTablesAreLocatedErrors) {
  const auto expectError = [&](const std::string& file, const std::string& text,
                               const std::string& want, const std::string& unit = "") {
    write(file, text);
    const std::string e = errorOf("{model: table, file: " + file + unit + "}");
    EXPECT_NE(e.find("materials.yaml:3:"), std::string::npos) << e;  // the config's line
    EXPECT_NE(e.find("file"), std::string::npos) << e;
    EXPECT_NE(e.find(want), std::string::npos) << e;
  };
  expectError("neg.csv", "0,1\n1e-9,-0.5\n", "neg.csv:2: weight -0.5 is negative (column 2");
  expectError("order.csv", "0,1\n2e-9,1\n1e-9,1\n", "order.csv:3: delays must increase (column 1");
  expectError("before.csv", "-1e-9,1\n1e-9,1\n", "before.csv:1: delay -1e-09 s is negative (column 1");
  expectError("ns.csv", "-1,1\n1,1\n", "ns.csv:1: delay -1 ns is negative", ", delay_unit: ns");
  expectError("nan.csv", "0,1\n1e-9,nan\n", "nan.csv:2:");
  expectError("text.csv", "0,1\n1e-9,x\n", "text.csv:2: expected 2 finite numbers");
  expectError("three.csv", "0,1,2\n1e-9,1,2\n", "three.csv:1: expected 2 columns");
  expectError("one.csv", "0,1\n", "needs at least 2 rows (delay, weight), got 1");
  expectError("zero.csv", "0,0\n1e-9,0\n", "zero.csv: the weight has no area");
  expectError("huge.csv", "0,1e300\n1e300,1e300\n", "area overflows");
  expectError("k.txt", "0,1\n", ".npy (n, 2) or two-column .csv");
  EXPECT_NE(errorOf("{model: table, file: missing.csv}").find("not found"), std::string::npos);
  const std::vector<float> flat = {0.f, 1.f, 1.f, 1.f, 2.f, 1.f};
  io::writeNpy(dir_ / "flat.npy", {6}, flat.data());
  EXPECT_NE(errorOf("{file: flat.npy}").find("expected shape (n, 2) (delay in s, weight), got (6)"),
            std::string::npos);
  const std::vector<float> negative = {0.f, 1.f, 1.f, -1.f};
  io::writeNpy(dir_ / "neg.npy", {2, 2}, negative.data());
  EXPECT_NE(errorOf("{file: neg.npy}").find("neg.npy row 1: weight -1 is negative (column 2"),
            std::string::npos);
  write("bad.npy", "not an npy");
  EXPECT_NE(errorOf("{file: bad.npy}").find("a scattering delay table .npy is a float32 or float64 (n, 2)"),
            std::string::npos);
  EXPECT_NE(errorOf("{file: neg.csv, delay_unit: fs}").find("must be s, ms, us, ns or ps"),
            std::string::npos);
  // A table too wide for the stage loads, and the stage refuses it (the
  // material table reports that at its key), before casting its reach.
  write("wide.csv", "0,1\n1e300,1\n");
  EXPECT_THROW(physics::responseTaps(parse("{file: wide.csv}"), kBin_s), std::invalid_argument);
  write("second.csv", "0,1\n1,1\n");
  EXPECT_THROW(physics::responseTaps(parse("{file: second.csv}"), kBin_s), std::invalid_argument);
  // A link is refused, not read through.
  write("real.csv", "0,1\n1e-9,1\n");
  std::filesystem::create_symlink(dir_ / "real.csv", dir_ / "link.csv");
  EXPECT_NO_THROW(parse("{file: real.csv}"));
  EXPECT_NE(errorOf("{file: link.csv}").find("symbolic link"), std::string::npos);
}

}  // namespace
}  // namespace tofsim::config
