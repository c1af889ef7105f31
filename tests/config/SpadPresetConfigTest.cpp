// SPAD device presets (`preset:`, sensors/SpadPresets.h) through the config
// layer: each preset gives its cited numbers, every explicit key wins over
// it, an unknown name is a located error listing the known ones, and the
// effective config reads back to the same sensor.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "ConfigNode.h"
#include "SensorKeysTest.h"
#include "support/TempDir.h"
#include "tofsim/config/ConfigKeys.h"
#include "tofsim/config/SensorConfig.h"
#include "tofsim/sensors/SpadPresets.h"

namespace tofsim::config {
namespace {

using namespace tofsim::sensors;

class SpadPresetConfigTest : public test::SensorKeysTest<SpadParams> {
 protected:
  SpadPresetConfigTest() : SensorKeysTest("spad") {}
};

TEST_F(SpadPresetConfigTest, PresetsGiveTheirCitedNumbers) {
  const SpadParams nlos = parse("    preset: nlos-gated-spad\n");
  EXPECT_EQ(nlos.preset, "nlos-gated-spad");
  EXPECT_EQ(nlos.mode, SpadMode::Synchronous);
  EXPECT_DOUBLE_EQ(nlos.bins.bin_width_s, 4e-12);  // PicoHarp 300 base resolution [PH300]
  EXPECT_DOUBLE_EQ(nlos.dead_time_s, 95e-9);       // TCSPC dead time [PH300]
  EXPECT_DOUBLE_EQ(nlos.jitter_fwhm_s, 50e-12);    // lower end of 50-500 ps [MH150]
  const SpadParams array = parse("    preset: spad512s\n");
  EXPECT_DOUBLE_EQ(array.bins.bin_width_s, 17e-12);     // gate shift [SPAD512S]
  EXPECT_DOUBLE_EQ(array.pde, 0.5);                     // PDP > 50 % [SPAD512S]
  EXPECT_DOUBLE_EQ(array.dark_count_rate_per_s, 25.0);  // DCR < 25 cps [SPAD512S]
  // Timing not published for the array: assumed, and listed as such (a note,
  // no source), not left at 0 (a sharper histogram than any capture).
  EXPECT_DOUBLE_EQ(array.pulse_fwhm_s, 30e-12);    // y-tal's default laser [TAL13]
  EXPECT_DOUBLE_EQ(array.jitter_fwhm_s, 100e-12);  // inside 50-500 ps [MH150]
  for (const SpadPresetValue& v : findSpadPreset("spad512s")->values) {
    const std::string key = v.key;
    if (key == "pulse_fwhm" || key == "jitter_fwhm") {
      EXPECT_EQ(v.source, nullptr) << key;
      EXPECT_NE(v.note, nullptr) << key;
    }
  }
  std::set<std::string> listed;
  for (const SpadPresetValue& v : findSpadPreset("spad512s")->values) listed.insert(v.key);
  EXPECT_TRUE(listed.count("pulse_fwhm") && listed.count("jitter_fwhm"));
  const SpadParams flash = parse("    preset: flash-lidar-fbk256\n");
  EXPECT_DOUBLE_EQ(flash.bins.bin_width_s, 250e-12);  // [FBK256]
  EXPECT_DOUBLE_EQ(flash.pde, 0.28);                  // IMX611's, listed as assumed
  EXPECT_EQ(flash.mode, SpadMode::Synchronous);       // first event [FBK256]
  // Without a preset, the library defaults.
  const SpadParams none = parse("    pde: 0.3\n");
  EXPECT_TRUE(none.preset.empty());
  EXPECT_EQ(none.bins.bin_width_s, SpadParams{}.bins.bin_width_s);
}

TEST_F(SpadPresetConfigTest, EveryPresetValueIsADeclaredKeyWithASourceOrANote) {
  std::set<std::string> keys;
  for (const ConfigKey& k : sensorConfigKeys()) keys.insert(k.path);
  for (const SpadPreset& preset : spadPresets()) {
    EXPECT_FALSE(preset.sources.empty()) << preset.name;
    for (const SpadPresetValue& v : preset.values) {
      const std::string key = v.key;  // a SPAD key, or an instrument-bins key
      EXPECT_TRUE(keys.count("spad." + key) || keys.count("bins." + key))
          << preset.name << ": " << key;
      EXPECT_TRUE((v.source != nullptr) != (v.note != nullptr)) << preset.name << ": " << v.key;
      // A cited key "[X]" resolves in the preset's source list.
      const std::string text = v.source ? v.source : v.note;
      for (std::size_t at = text.find('['); at != std::string::npos; at = text.find('[', at + 1)) {
        // "[MH150 p.10]" cites [MH150]
        const std::string cited = text.substr(at, text.find_first_of("] ", at) - at) + "]";
        bool listed = false;
        for (const char* s : preset.sources) listed = listed || std::string(s).rfind(cited, 0) == 0;
        EXPECT_TRUE(listed) << preset.name << " cites " << cited << " without listing it";
      }
    }
    EXPECT_EQ(findSpadPreset(preset.name), &preset);
  }
}

TEST_F(SpadPresetConfigTest, ExplicitKeysWinOverThePreset) {
  const SpadParams p = parse(
      "    preset: spad512s\n    pde: 0.4\n    bin_width: \"10 ps\"\n    mode: free_running\n");
  EXPECT_DOUBLE_EQ(p.pde, 0.4);
  EXPECT_DOUBLE_EQ(p.bins.bin_width_s, 10e-12);
  EXPECT_EQ(p.mode, SpadMode::FreeRunning);
  EXPECT_DOUBLE_EQ(p.dark_count_rate_per_s, 25.0);  // not given: the preset's
  // An explicit irf replaces the preset's jitter (it is no explicit jitter_fwhm).
  std::ofstream(dir_ / "irf.csv") << "time,value\n0,0\n1e-12,1\n2e-12,0.5\n3e-12,0\n";
  const SpadParams gated = parse("    preset: nlos-gated-spad\n    irf: {file: irf.csv}\n");
  EXPECT_EQ(gated.jitter_fwhm_s, 0.0);
  EXPECT_TRUE(gated.irf.present());
  EXPECT_DOUBLE_EQ(gated.bins.bin_width_s, 4e-12);
  // An explicit jitter_fwhm with an irf is still an error.
  EXPECT_NE(
      errorOf("    preset: nlos-gated-spad\n    jitter_fwhm: 30 ps\n    irf: {file: irf.csv}\n")
          .find("remove `jitter_fwhm`"),
      std::string::npos);
}

TEST_F(SpadPresetConfigTest, UnknownPresetIsALocatedErrorListingTheKnownNames) {
  const std::string error = errorOf("    pde: 0.5\n    preset: spad1024\n");
  EXPECT_NE(error.find("sensor.yaml:4"), std::string::npos) << error;
  EXPECT_NE(error.find("preset"), std::string::npos) << error;
  EXPECT_NE(error.find("unknown SPAD preset 'spad1024'"), std::string::npos) << error;
  for (const SpadPreset& preset : spadPresets()) {
    EXPECT_NE(error.find(preset.name), std::string::npos) << error;
  }
}

TEST_F(SpadPresetConfigTest, EffectiveConfigReadsBackToTheSameSensor) {
  const SpadParams p = parse("    preset: nlos-gated-spad\n    pde: 0.2\n");
  SensorSpec spec;
  spec.name = "spad";
  spec.params = p;
  YAML::Node doc;
  doc["sensors"] = sensorsToYaml({spec});
  EXPECT_EQ(doc["sensors"][0]["preset"].as<std::string>(), "nlos-gated-spad");
  const ConfigNode again(YAML::Load(YAML::Dump(doc)), "effective.yaml");
  const SpadParams back = std::get<SpadParams>(parseSensors(again.child("sensors")).front().params);
  EXPECT_EQ(back.preset, p.preset);
  EXPECT_EQ(back.bins.bin_width_s, p.bins.bin_width_s);
  EXPECT_EQ(back.dead_time_s, p.dead_time_s);
  EXPECT_EQ(back.jitter_fwhm_s, p.jitter_fwhm_s);
  EXPECT_EQ(back.pde, 0.2);
  EXPECT_EQ(back.cycles, p.cycles);
}

}  // namespace
}  // namespace tofsim::config
