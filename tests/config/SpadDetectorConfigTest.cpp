// The SPAD detector keys of the event engine (multi-stop TDC, afterpulses):
// bad values and combinations are located errors.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "ConfigNode.h"
#include "tofsim/config/SensorConfig.h"

namespace tofsim::config {
namespace {

/// The message of the InputError that parsing the sensors of `text` throws ("" if none).
std::string errorOf(const std::string& text) {
  try {
    const ConfigNode root(YAML::Load(text), "test.yaml");
    parseSensors(root.child("sensors"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

struct Case {
  std::string yaml, where, key, words;
};

void expectErrors(const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    const std::string message = errorOf(c.yaml);
    EXPECT_NE(message.find(c.where + ": " + c.key + ": "), std::string::npos)
        << c.yaml << " -> " << message;
    EXPECT_NE(message.find(c.words), std::string::npos) << c.yaml << " -> " << message;
  }
}

TEST(SpadDetectorConfigTest, TdcStopsOutOfRangeOrFreeRunningAreLocatedErrors) {
  expectErrors({
      {"sensors:\n  - type: spad\n    tdc_stops: -1\n", "test.yaml:3:16", "sensors[0].tdc_stops",
       "must be in [0"},
      {"sensors:\n  - type: spad\n    mode: free_running\n    tdc_stops: 4\n", "test.yaml:4:16",
       "sensors[0].tdc_stops", "is for `mode: synchronous`"},
  });
  EXPECT_EQ(errorOf("sensors:\n  - type: spad\n    tdc_stops: 0\n    dead_time: 95 ns\n"), "");
}

TEST(SpadDetectorConfigTest, AfterpulseMixturesThatDoNotAgreeAreLocatedErrors) {
  const std::string ap = "sensors:\n  - type: spad\n    afterpulse_probability: 0.1\n";
  expectErrors({
      {ap + "    afterpulse_delay: [2 ns, -3 ns]\n", "test.yaml:4:30",
       "sensors[0].afterpulse_delay[1]", "delay must be > 0"},
      {ap + "    afterpulse_delay: 0 ns\n", "test.yaml:4:23", "sensors[0].afterpulse_delay",
       "delay must be > 0"},
      {ap + "    afterpulse_delay: [2 ns, 30 ns]\n    afterpulse_weights: [1, 2, 3]\n",
       "test.yaml:5:25", "sensors[0].afterpulse_weights", "gives 3 weights for 2"},
      {ap + "    afterpulse_weights: [0.5, 0.5]\n", "test.yaml:4:25",
       "sensors[0].afterpulse_weights", "gives 2 weights for 1"},
      {ap + "    afterpulse_delay: [2 ns, 30 ns]\n    afterpulse_weights: [1, -1]\n",
       "test.yaml:5:29", "sensors[0].afterpulse_weights[1]", "weight must be >= 0"},
      {ap + "    afterpulse_delay: [2 ns, 30 ns]\n    afterpulse_weights: [0, 0]\n",
       "test.yaml:5:25", "sensors[0].afterpulse_weights", "must not all be 0"},
      {ap + "    afterpulse_count: binomial\n", "test.yaml:4:23", "sensors[0].afterpulse_count",
       "bernoulli or poisson"},
      {"sensors:\n  - type: spad\n    afterpulse_count: poisson\n", "test.yaml:3:23",
       "sensors[0].afterpulse_count", "no effect while afterpulse_probability is 0"},
      {"sensors:\n  - type: spad\n    afterpulse_traps: keep\n", "test.yaml:3:23",
       "sensors[0].afterpulse_traps", "no effect while afterpulse_probability is 0"},
  });
}

TEST(SpadDetectorConfigTest, AfterpulseMixtureSurvivesTheEffectiveConfig) {
  const auto parse = [](const std::string& text) {
    const ConfigNode root(YAML::Load(text), "test.yaml");
    return std::get<sensors::SpadParams>(parseSensors(root.child("sensors"))[0].params);
  };
  const sensors::SpadParams p = parse(
      "sensors:\n  - type: spad\n    afterpulse_probability: 0.05\n    afterpulse_count: poisson\n"
      "    afterpulse_delay: [10 ns, 80 ns]\n    afterpulse_weights: [1, 1]\n"
      "    afterpulse_traps: keep\n    tdc_stops: 4\n    dead_time: 95 ns\n");
  EXPECT_EQ(p.afterpulse_delays_s, (std::vector<double>{10e-9, 80e-9}));
  EXPECT_EQ(p.afterpulse_weights, (std::vector<double>{1.0, 1.0}));
  EXPECT_EQ(p.afterpulse_count, sensors::SpadAfterpulseCount::Poisson);
  EXPECT_EQ(p.afterpulse_traps, sensors::SpadAfterpulseTraps::Keep);
  EXPECT_EQ(p.tdc_stops, 4);
  YAML::Node doc;
  doc["sensors"] = sensorsToYaml({sensors::SensorSpec{"spad", p}});
  const sensors::SpadParams again = parse(YAML::Dump(doc));
  EXPECT_EQ(again.afterpulse_delays_s, p.afterpulse_delays_s);
  EXPECT_EQ(again.afterpulse_weights, p.afterpulse_weights);
  EXPECT_EQ(again.afterpulse_count, p.afterpulse_count);
  EXPECT_EQ(again.afterpulse_traps, p.afterpulse_traps);
  EXPECT_EQ(again.tdc_stops, p.tdc_stops);
  // One delay stays one duration (the form of the configs before mixtures).
  EXPECT_EQ(parse("sensors:\n  - type: spad\n    afterpulse_delay: 5 ns\n").afterpulse_delays_s,
            std::vector<double>{5e-9});
}

}  // namespace
}  // namespace tofsim::config
