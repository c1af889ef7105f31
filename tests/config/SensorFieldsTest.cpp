// The sensor parameter tables (sensors/SensorFields.h) against the structs:
// the documented default of every key, written into a config, must parse to
// the struct's own default. The rows are derived from the structs, so this
// fails when the derivation (or a hand-written Custom row) disagrees.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <set>
#include <string>
#include <vector>

#include "ConfigNode.h"
#include "tofsim/config/ConfigKeys.h"
#include "tofsim/config/SensorConfig.h"

namespace tofsim::config {
namespace {

/// The effective YAML of one `sensors:` entry given as text.
std::string effective(const std::string& entry) {
  const ConfigNode root(YAML::Load("sensors:\n  - " + entry + "\n"), "test.yaml");
  YAML::Node doc;
  doc["sensors"] = sensorsToYaml(parseSensors(root.child("sensors")));
  return YAML::Dump(doc);
}

TEST(SensorFieldsTest, DocumentedDefaultsReadBackAsTheStructDefaults) {
  // Defaults that are words, not values ("the render's", "all rows").
  const std::set<std::string> described = {
      "common.type",       "common.name",      "common.channel_weights",
      "bins.bin_width",    "bins.bin_offset",  "bins.bins",
      "streak.rows",       "spad.plot_pixels", "spad.irf",
      "spad.preset",       "spad.tdc_dnl",     "spad.dark_count_map",
      "cwtof.correlation", "cwtof.delay_map",  "cwtof.gain_map",
      "cwtof.offset_map",  "cwtof.companding", "cwtof.capture_order",
      "cwtof.noise_table", "cwtof.preset",     "common.channel"};
  const std::set<std::string> words = {"spad.afterpulse_weights"};  // "equal"
  // A file whose default is its absence ("none (exponentials)").
  const std::set<std::string> files = {"spad.afterpulse_delay_table"};
  int checked = 0;
  for (const ConfigKey& key : sensorConfigKeys()) {
    const std::string path = key.path;
    if (described.count(path) || words.count(path) || files.count(path)) continue;
    const std::string group = path.substr(0, path.find('.'));
    const std::string name = path.substr(path.find('.') + 1);
    const std::string type = group == "common" ? "streak" : group;
    std::string value = key.defaultValue;
    value = value.substr(0, value.find(" ("));  // "0 (automatic)": the value, not the note
    SCOPED_TRACE(path + ": " + value);
    EXPECT_EQ(effective("type: " + type + "\n    " + name + ": " + value),
              effective("type: " + type))
        << "the documented default of `" << path << "` is not the struct's";
    ++checked;
  }
  EXPECT_GE(checked, 30);  // every value-like key, not none by a bad filter
}

// The tables give the rows the hand-kept list used to: the unit and range
// columns come from the kind.
TEST(SensorFieldsTest, RowsComeFromTheTables) {
  std::vector<std::string> paths;
  for (const ConfigKey& key : sensorConfigKeys()) {
    const std::string path = key.path;
    if (path == "spad.dead_time") {
      EXPECT_STREQ(key.type, "duration");
      EXPECT_STREQ(key.range, ">= 0");
      EXPECT_STREQ(key.defaultValue, "0");
      EXPECT_STREQ(key.unit, "s");
    }
    if (path == "spad.pde") {
      EXPECT_STREQ(key.range, "in [0, 1]");
      EXPECT_STREQ(key.defaultValue, "0.3");
    }
    if (path == "cwtof.phase_steps") {
      EXPECT_STREQ(key.range, ">= 3");
    }
    if (path == "spad.mode") {
      EXPECT_STREQ(key.defaultValue, "synchronous");
    }
    paths.push_back(path);
  }
  const std::set<std::string> unique(paths.begin(), paths.end());
  EXPECT_EQ(unique.size(), paths.size()) << "a key is declared twice";
}

}  // namespace
}  // namespace tofsim::config
