// A CW-ToF device preset in the sensor JSON (SensorParametersJson.h): its
// name, device line and pixel array, every value it sets as sourced (with
// the source) or assumed (with why), and the sources those cite; none
// without a preset.

#include <gtest/gtest.h>

#include <string>

#include "SensorParametersJson.h"
#include "tofsim/pipeline/SensorMetadata.h"
#include "tofsim/sensors/CwTofPresets.h"
#include "tofsim/sensors/RunSensor.h"

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

TEST(CwTofPresetJsonTest, KinectV2OutputsDocumentTheirCaptureOrder) {
  TimeAxis axis;
  axis.bin_width_s = 20e-12;
  axis.bins = 400;
  TransientVolume v(3, 2, axis, {"c0"});
  for (int32_t x = 0; x < 3; ++x) v.at(1, x, 100 + 50 * x, 0) = 500.0f;
  CwTofParams p;
  findCwTofPreset("kinect-v2")->apply(p);
  p.preset = "kinect-v2";
  const SensorSpec spec{"kinect", p};
  SensorRunInfo run{&spec, axis, 1, sensorWarnings(spec, shapeOf(v), nullptr)};
  const std::vector<SensorOutput> outs = runSensor(spec, {&v, nullptr, nullptr, nullptr, 1});
  bool found = false;
  for (const NamedMetadata& m : sensorMetadata(run, outs, false)) {
    if (m.name != "cwtof_raw_sequence") continue;
    found = true;
    const nlohmann::json j = nlohmann::json::parse(m.json);
    EXPECT_EQ(j["shape"], (std::vector<int64_t>{9, 2, 3}));
    EXPECT_TRUE(j["axes_doc"].contains("capture_index"));
    EXPECT_EQ(j["sensor"]["parameters"]["preset"]["name"], "kinect-v2");
    EXPECT_EQ(j["sensor"]["parameters"]["capture"]["order"].size(), 9u);
    // 3 x 2 pixels is not the device's 512 x 424: the run says so.
    ASSERT_EQ(j["sensor"]["warnings"].size(), 1u);
    EXPECT_NE(j["sensor"]["warnings"][0].get<std::string>().find("512 x 424"), std::string::npos);
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace tofsim::pipeline
