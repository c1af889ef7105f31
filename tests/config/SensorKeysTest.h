#pragma once
// A sensor's keys through the config layer, in the test's temporary folder:
// SensorKeysTest parses them alone, as a `sensors:` entry is parsed
// (parseSensors, then the unused-key report; `keys` are the entry's indented
// YAML lines under `- type: <type>` in sensor.yaml); RunSensorKeysTest loads
// them as the last sensor of a whole run config (loadRunConfig of test.yaml:
// the given run text, ending in the sensor's `- type:` line, then `keys`),
// for the checks that need the camera or the time axis. Files the keys name
// are relative to that folder; errors are located in its YAML file.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include "ConfigNode.h"
#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/config/SensorConfig.h"
#include "tofsim/util/Error.h"

namespace tofsim::test {

template <class Params>
class SensorKeysTest : public TempDirTest {
 protected:
  explicit SensorKeysTest(std::string type) : type_(std::move(type)) {}

  Params parse(const std::string& keys) {
    const std::filesystem::path file = dir_ / "sensor.yaml";
    std::ofstream(file) << "sensors:\n  - type: " << type_ << "\n" << keys;
    const config::ConfigNode root(YAML::LoadFile(file.string()), file.string());
    const std::vector<sensors::SensorSpec> specs = config::parseSensors(root.child("sensors"));
    root.reportUnusedKeys();
    return std::get<Params>(specs.front().params);
  }
  /// The InputError's text, or "" when the keys parse.
  std::string errorOf(const std::string& keys) {
    try {
      parse(keys);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }

 private:
  std::string type_;
};

template <class Params>
class RunSensorKeysTest : public TempDirTest {
 protected:
  explicit RunSensorKeysTest(const char* run) : run_(run) {}

  std::filesystem::path write(const std::string& keys) {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    const std::filesystem::path path = dir_ / "test.yaml";
    std::ofstream(path) << run_ << keys;
    return path;
  }
  Params load(const std::string& keys) {
    const config::RunConfig c = config::loadRunConfig(write(keys));
    return std::get<Params>(c.sensors.back().params);
  }
  /// The InputError's text; a test failure when the keys load.
  std::string errorOf(const std::string& keys) {
    try {
      config::loadRunConfig(write(keys));
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no error for:\n" << keys;
    return "";
  }

 private:
  const char* run_;
};

}  // namespace tofsim::test
