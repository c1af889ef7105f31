// The effective config keeps a time in the form the user wrote it (issue
// 44, item 11): `bin_width: 1 cm` stays "1 cm", not "33.35640951981521 ps",
// while the config's value (what the metadata writes) is the seconds light
// takes to cover 1 cm; a length is written as the shortest length that reads
// back exactly ("30 cm" as "0.3 m"); times written in ps or ns keep their
// forms; every form reads back to the same double.

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::config {
namespace {

class EffectiveUnitsConfigTest : public test::TempDirTest {
 protected:
  RunConfig load(const std::string& time, const std::string& sensor = "") {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    const auto path = dir_ / "c.yaml";
    std::ofstream(path) << "scene: scene.gltf\ncamera: {}\nlight: {type: point, position: [0, 0, "
                           "1]}\ntime: "
                        << time << "\n"
                        << sensor;
    return loadRunConfig(path);
  }
  RunConfig reload(const RunConfig& c) {
    const auto path = dir_ / "effective.yaml";
    std::ofstream(path) << effectiveConfigYaml(c);
    return loadRunConfig(path);
  }
};

bool has(const std::string& text, const std::string& line) {
  return text.find(line) != std::string::npos;
}

TEST_F(EffectiveUnitsConfigTest, ALengthStaysALength) {
  const RunConfig c = load("{start: 1.5 m, bin_width: 1 cm, bins: 100}");
  EXPECT_DOUBLE_EQ(c.render.time.bin_width_s, 0.01 / kSpeedOfLight_m_per_s);
  const std::string yaml = effectiveConfigYaml(c);
  EXPECT_TRUE(has(yaml, "bin_width: 1 cm")) << yaml;
  EXPECT_TRUE(has(yaml, "start: 1.5 m")) << yaml;
  const RunConfig again = reload(c);
  EXPECT_EQ(again.render.time.bin_width_s, c.render.time.bin_width_s);
  EXPECT_EQ(again.render.time.start_s, c.render.time.start_s);
  EXPECT_EQ(effectiveConfigYaml(again), yaml);
}

TEST_F(EffectiveUnitsConfigTest, PicosecondsAndSensorDurationsKeepTheirForms) {
  const RunConfig c = load("{start: 5 ns, bin_width: 10 ps, bins: 100}",
                           "sensors:\n  - type: spad\n    cycles: 10\n    pulse_fwhm: 70 ps\n"
                           "    bin_offset: 30 cm\n");
  const std::string yaml = effectiveConfigYaml(c);
  EXPECT_TRUE(has(yaml, "bin_width: 10 ps")) << yaml;
  EXPECT_TRUE(has(yaml, "start: 5000 ps")) << yaml;  // time: writes ps, as before
  EXPECT_TRUE(has(yaml, "pulse_fwhm: 70 ps")) << yaml;
  EXPECT_TRUE(has(yaml, "bin_offset: 0.3 m")) << yaml;  // a length, in its shortest form
  EXPECT_EQ(effectiveConfigYaml(reload(c)), yaml);
}

}  // namespace
}  // namespace tofsim::config
