// CW-ToF device presets (`preset:`, sensors/CwTofPresets.h) through the
// config layer: each preset gives its cited numbers, every explicit key wins
// over it, an unknown name is a located error listing the known ones, a
// preset's capture order that the config's own frequencies no longer fit is
// a located error, and the effective config reads back to the same sensor.

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
#include "tofsim/sensors/CwTofPresets.h"

namespace tofsim::config {
namespace {

using namespace tofsim::sensors;

class CwTofPresetConfigTest : public test::SensorKeysTest<CwTofParams> {
 protected:
  CwTofPresetConfigTest() : SensorKeysTest("cwtof") {}
  // p through the effective config's writer and read again.
  static CwTofParams roundTrip(const CwTofParams& p) {
    YAML::Node doc;
    doc["sensors"] = sensorsToYaml({SensorSpec{"cwtof", p}});
    const ConfigNode again(YAML::Load(YAML::Dump(doc)), "effective.yaml");
    return std::get<CwTofParams>(parseSensors(again.child("sensors")).front().params);
  }
};

TEST_F(CwTofPresetConfigTest, PresetsGiveTheirCitedNumbers) {
  const CwTofParams kinect = parse("    preset: kinect-v2\n");
  EXPECT_EQ(kinect.preset, "kinect-v2");
  EXPECT_EQ(kinect.frequencies_Hz, (std::vector<double>{80e6, 16e6, 120e6}));  // [LF2]
  EXPECT_EQ(kinect.phase_steps, 3);                                            // [LF2]
  // libfreenect2's raw k is tofsim's step (3 - k) mod 3, frequency by frequency.
  const std::vector<CwTofCaptureStep> order{{0, 0}, {0, 2}, {0, 1}, {1, 0}, {1, 2},
                                            {1, 1}, {2, 0}, {2, 2}, {2, 1}};
  EXPECT_EQ(kinect.capture_order, order);
  EXPECT_EQ(kinect.taps, 2);
  EXPECT_EQ(kinect.adc_bits, 16);  // int16 [LF2], 32768 its zero
  EXPECT_EQ(kinect.adc_offset_dn, 32768.0);
  EXPECT_EQ(kinect.max_depth_m, 6.0);  // [FLAT]
  const char* modes[] = {"azure-kinect-nfov-unbinned", "azure-kinect-nfov-2x2",
                         "azure-kinect-wfov-2x2", "azure-kinect-wfov-unbinned"};
  const double ranges[] = {4.0, 5.8, 3.0, 2.5};                               // [AKVIEW]
  const int sizes[][2] = {{640, 576}, {320, 288}, {512, 512}, {1024, 1024}};  // [AKDOC]
  for (int i = 0; i < 4; ++i) {
    const CwTofParams ak = parse(std::string("    preset: ") + modes[i] + "\n");
    EXPECT_EQ(ak.max_depth_m, ranges[i]) << modes[i];
    EXPECT_EQ(findCwTofPreset(modes[i])->width, sizes[i][0]) << modes[i];
    EXPECT_EQ(findCwTofPreset(modes[i])->height, sizes[i][1]) << modes[i];
    double mean = 0.0;  // the assumed set: inside 10-320 MHz, averaging 200 MHz [AK1807]
    for (double f : ak.frequencies_Hz) {
      EXPECT_TRUE(f >= 10e6 && f <= 320e6) << f;
      mean += f / static_cast<double>(ak.frequencies_Hz.size());
    }
    EXPECT_NEAR(mean, 200e6, 1.0);
  }
  const CwTofParams pmd = parse("    preset: pmd-generic\n");  // [CAMSIM]
  EXPECT_EQ(pmd.frequencies_Hz, std::vector<double>{10e6});
  EXPECT_EQ(pmd.phase_steps, 4);
  EXPECT_EQ(pmd.taps, 2);
  EXPECT_EQ(pmd.modulation_contrast, 0.75);
  EXPECT_EQ(pmd.full_well_e, 100'000.0);
  EXPECT_DOUBLE_EQ(pmd.integration_time_s, 1.0 / 60.0);
  // Without a preset, the library defaults.
  const CwTofParams none = parse("    phase_steps: 5\n");
  EXPECT_TRUE(none.preset.empty());
  EXPECT_EQ(none.frequencies_Hz, CwTofParams{}.frequencies_Hz);
  EXPECT_TRUE(none.capture_order.empty());
}

TEST_F(CwTofPresetConfigTest, EveryPresetValueIsADeclaredKeyWithASourceOrANote) {
  std::set<std::string> keys;
  for (const ConfigKey& k : sensorConfigKeys()) keys.insert(k.path);
  EXPECT_EQ(keys.count("cwtof.preset"), 1u);
  for (const CwTofPreset& preset : cwtofPresets()) {
    EXPECT_FALSE(preset.sources.empty()) << preset.name;
    for (const PresetValue& v : preset.values) {
      EXPECT_TRUE(keys.count("cwtof." + std::string(v.key))) << preset.name << ": " << v.key;
      EXPECT_TRUE((v.source != nullptr) != (v.note != nullptr)) << preset.name << ": " << v.key;
      // A cited key "[X]" resolves in the preset's source list.
      const std::string text = v.source ? v.source : v.note;
      for (std::size_t at = text.find('['); at != std::string::npos; at = text.find('[', at + 1)) {
        const std::string cited = text.substr(at, text.find_first_of("] ,", at) - at) + "]";
        if (cited.find_first_not_of("[]0123456789") == std::string::npos) continue;  // a list
        bool listed = false;
        for (const char* s : preset.sources) listed = listed || std::string(s).rfind(cited, 0) == 0;
        EXPECT_TRUE(listed) << preset.name << " cites " << cited << " without listing it";
      }
    }
    EXPECT_EQ(findCwTofPreset(preset.name), &preset);
  }
}

TEST_F(CwTofPresetConfigTest, ExplicitKeysWinOverThePreset) {
  const CwTofParams p = parse(
      "    preset: kinect-v2\n    max_depth: 4.5 m\n    adc_offset: 1000\n    taps: 1\n"
      "    capture_order: [[2, 0], [2, 1], [2, 2], [1, 0], [1, 1], [1, 2], [0, 0], [0, 1], "
      "[0, 2]]\n");
  EXPECT_EQ(p.max_depth_m, 4.5);
  EXPECT_EQ(p.adc_offset_dn, 1000.0);
  EXPECT_EQ(p.taps, 1);
  EXPECT_EQ(p.capture_order.front(), (CwTofCaptureStep{2, 0}));
  EXPECT_EQ(p.frequencies_Hz, (std::vector<double>{80e6, 16e6, 120e6}));  // not given: the preset's
  EXPECT_EQ(p.adc_bits, 16);
  // With their own order, new frequencies take it.
  const CwTofParams two = parse(
      "    preset: kinect-v2\n    frequencies: [20 MHz, 100 MHz]\n"
      "    capture_order: [[0, 0], [0, 1], [0, 2], [1, 0], [1, 1], [1, 2]]\n");
  EXPECT_EQ(two.capture_order.size(), 6u);
  EXPECT_EQ(two.capture_order[1], (CwTofCaptureStep{0, 1}));
}

// Issue 44 item 7: new frequencies or steps over a preset with a capture
// order derive theirs from the preset's pattern (Kinect: each frequency in
// turn, its steps descending from 0); `null` derives it too; `[]` is a
// located error that shows an order to write.
TEST_F(CwTofPresetConfigTest, NewFrequenciesOrStepsDeriveThePresetsCaptureOrder) {
  const CwTofParams two = parse("    preset: kinect-v2\n    frequencies: [20 MHz, 100 MHz]\n");
  EXPECT_EQ(two.capture_order, (std::vector<CwTofCaptureStep>{
                                   {0, 0}, {0, 2}, {0, 1}, {1, 0}, {1, 2}, {1, 1}}));
  const CwTofParams four = parse(
      "    preset: kinect-v2\n    frequencies: 40 MHz\n    phase_steps: 4\n"
      "    capture_order: null\n");
  EXPECT_EQ(four.capture_order,
            (std::vector<CwTofCaptureStep>{{0, 0}, {0, 3}, {0, 2}, {0, 1}}));
  // The derived order is written out and reads back as itself.
  EXPECT_EQ(roundTrip(two).capture_order, two.capture_order);
  const std::string empty = errorOf(
      "    preset: kinect-v2\n    frequencies: [20 MHz, 100 MHz]\n    capture_order: []\n");
  EXPECT_NE(empty.find("sensor.yaml:5"), std::string::npos) << empty;
  EXPECT_NE(empty.find("capture_order: lists no raws"), std::string::npos) << empty;
  EXPECT_NE(empty.find("e.g. [[0, 0], [0, 2], [0, 1], [1, 0], [1, 2], [1, 1]]"),
            std::string::npos)
      << empty;
  // Without a preset, null is the default order (frequency-major).
  EXPECT_TRUE(parse("    frequencies: 40 MHz\n    capture_order: null\n").capture_order.empty());
}

TEST_F(CwTofPresetConfigTest, UnknownPresetIsALocatedErrorListingTheKnownNames) {
  const std::string error = errorOf("    phase_steps: 3\n    preset: kinect-v3\n");
  EXPECT_NE(error.find("sensor.yaml:4"), std::string::npos) << error;
  EXPECT_NE(error.find("unknown CW-ToF preset 'kinect-v3'"), std::string::npos) << error;
  for (const CwTofPreset& preset : cwtofPresets()) {
    EXPECT_NE(error.find(preset.name), std::string::npos) << error;
  }
}

TEST_F(CwTofPresetConfigTest, EffectiveConfigReadsBackToTheSameSensor) {
  for (const CwTofPreset& preset : cwtofPresets()) {
    const CwTofParams p = parse(std::string("    preset: ") + preset.name + "\n    ambient: 5\n");
    SensorSpec spec{"cwtof", p};
    YAML::Node doc;
    doc["sensors"] = sensorsToYaml({spec});
    EXPECT_EQ(doc["sensors"][0]["preset"].as<std::string>(), preset.name);
    const std::string text = YAML::Dump(doc);
    const ConfigNode again(YAML::Load(text), "effective.yaml");
    const CwTofParams back =
        std::get<CwTofParams>(parseSensors(again.child("sensors")).front().params);
    YAML::Node twice;
    twice["sensors"] = sensorsToYaml({SensorSpec{"cwtof", back}});
    EXPECT_EQ(YAML::Dump(twice), text) << preset.name;
    EXPECT_EQ(back.capture_order, p.capture_order);
    EXPECT_EQ(back.frequencies_Hz, p.frequencies_Hz);
  }
}

}  // namespace
}  // namespace tofsim::config
