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

}  // namespace
}  // namespace tofsim::config
