// A CW-ToF device preset in the sensor JSON (SensorParametersJson.h): its
// name, device line and pixel array, every value it sets as sourced (with
// the source) or assumed (with why), and the sources those cite; none
// without a preset.

#include <gtest/gtest.h>

#include <string>

#include "SensorParametersJson.h"
#include "tofsim/sensors/CwTofPresets.h"

namespace tofsim::pipeline {
namespace {

using namespace tofsim::sensors;

TEST(CwTofPresetJsonTest, EveryPresetListsItsSourcedAndAssumedValues) {
  TimeAxis render;
  render.bin_width_s = 20e-12;
  render.bins = 100;
  for (const CwTofPreset& preset : cwtofPresets()) {
    SCOPED_TRACE(preset.name);
    CwTofParams p;
    preset.apply(p);
    p.preset = preset.name;
    const nlohmann::ordered_json j = sensorParametersJson(SensorParams{p}, render);
    ASSERT_TRUE(j.contains("preset"));
    const nlohmann::ordered_json& meta = j["preset"];
    EXPECT_EQ(meta["name"], preset.name);
    EXPECT_EQ(meta["device"], preset.device);
    EXPECT_EQ(meta.contains("device_image"), preset.width > 0);
    EXPECT_EQ(meta["sources"].size(), preset.sources.size());
    std::size_t listed = 0;
    for (const PresetValue& v : preset.values) {
      const char* group = v.source ? "sourced" : "assumed";
      ASSERT_TRUE(meta[group].contains(v.key)) << v.key;
      EXPECT_EQ(meta[group][v.key], v.source ? v.source : v.note);
      ++listed;
    }
    EXPECT_EQ(meta["sourced"].size() + meta["assumed"].size(), listed);
    // The preset's values are the parameters written beside it.
    EXPECT_EQ(j["frequencies_Hz"].get<std::vector<double>>(), p.frequencies_Hz);
  }
  // Azure Kinect's frequencies are not published: assumed, saying so.
  const nlohmann::ordered_json ak =
      sensorParametersJson(SensorParams{[] {
                             CwTofParams p;
                             findCwTofPreset("azure-kinect-nfov-unbinned")->apply(p);
                             p.preset = "azure-kinect-nfov-unbinned";
                             return p;
                           }()},
                           render)["preset"];
  EXPECT_TRUE(ak["assumed"].contains("frequencies"));
  EXPECT_TRUE(ak["sourced"].contains("max_depth"));
  EXPECT_FALSE(sensorParametersJson(SensorParams{CwTofParams{}}, render).contains("preset"));
}

}  // namespace
}  // namespace tofsim::pipeline
