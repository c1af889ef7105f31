// SPAD crosstalk keys through the config layer: parsed with their units,
// written back by the effective config to the same sensor, and bad values
// (a neighbourhood other than 4 or 8, a probability outside [0, 1], a
// negative delay, a delay with a gate) are located errors.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "ConfigNode.h"
#include "tofsim/config/SensorConfig.h"

namespace tofsim::config {
namespace {

using namespace tofsim::sensors;

std::vector<SensorSpec> parse(const std::string& keys) {
  const ConfigNode root(YAML::Load("sensors:\n  - type: spad\n" + keys), "test.yaml");
  std::vector<SensorSpec> specs = parseSensors(root.child("sensors"));
  root.reportUnusedKeys();
  return specs;
}

std::string errorOf(const std::string& keys) {
  try {
    parse(keys);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SpadCrosstalkConfigTest, ParsesAndRoundTrips) {
  const std::vector<SensorSpec> specs = parse(
      "    crosstalk_probability: 0.05\n    crosstalk_neighbours: 8\n"
      "    crosstalk_delay: 15 ns\n");
  const auto& p = std::get<SpadParams>(specs[0].params);
  EXPECT_DOUBLE_EQ(p.crosstalk_probability, 0.05);
  EXPECT_EQ(p.crosstalk_neighbours, CrosstalkNeighbours::Eight);
  EXPECT_DOUBLE_EQ(p.crosstalk_delay_s, 15e-9);
  YAML::Node doc;
  doc["sensors"] = sensorsToYaml(specs);
  const ConfigNode again(doc, "effective.yaml");
  const SpadParams q = std::get<SpadParams>(parseSensors(again.child("sensors"))[0].params);
  EXPECT_DOUBLE_EQ(q.crosstalk_probability, p.crosstalk_probability);
  EXPECT_EQ(q.crosstalk_neighbours, p.crosstalk_neighbours);
  EXPECT_DOUBLE_EQ(q.crosstalk_delay_s, p.crosstalk_delay_s);
  // The defaults: none, 4 neighbours, prompt.
  const SpadParams d = std::get<SpadParams>(parse("    pde: 0.3\n")[0].params);
  EXPECT_EQ(d.crosstalk_probability, 0.0);
  EXPECT_EQ(d.crosstalk_neighbours, CrosstalkNeighbours::Four);
  EXPECT_EQ(d.crosstalk_delay_s, 0.0);
}

TEST(SpadCrosstalkConfigTest, BadValuesAreLocatedErrors) {
  struct Case {
    std::string keys, where, words;
  };
  const std::vector<Case> cases = {
      {"    crosstalk_neighbours: 6\n",
       "test.yaml:3:27: sensors[0].crosstalk_neighbours: ", "must be 4 or 8 (got '6')"},
      {"    crosstalk_probability: 1.5\n",
       "test.yaml:3:28: sensors[0].crosstalk_probability: ", "must be in [0, 1]"},
      {"    crosstalk_delay: -1 ns\n",
       "test.yaml:3:22: sensors[0].crosstalk_delay: ", "must be >= 0"},
      {"    crosstalk_probability: 0.01\n    crosstalk_delay: 1 ns\n    gate_width: 5 ns\n"
       "    engine: fast\n",
       "test.yaml:4:22: sensors[0].crosstalk_delay: ", "with a gate"},
  };
  for (const Case& c : cases) {
    const std::string message = errorOf(c.keys);
    EXPECT_NE(message.find(c.where), std::string::npos) << c.keys << " -> " << message;
    EXPECT_NE(message.find(c.words), std::string::npos) << c.keys << " -> " << message;
  }
  // Prompt crosstalk with a gate is modelled.
  EXPECT_EQ(errorOf("    crosstalk_probability: 0.01\n    gate_width: 5 ns\n"), "");
  // Delayed crosstalk with a gate too, by the exact array driver (`auto`, `exact`).
  for (const char* engine : {"", "    engine: exact\n"}) {
    EXPECT_EQ(errorOf(std::string("    crosstalk_probability: 0.01\n    crosstalk_delay: 1 ns\n"
                                  "    gate_width: 5 ns\n") +
                      engine),
              "");
  }
}

}  // namespace
}  // namespace tofsim::config
