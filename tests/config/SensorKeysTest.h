#pragma once
// A sensor's keys parsed alone, as the config layer parses a `sensors:`
// entry (parseSensors, then the unused-key report), in the test's temporary
// folder: `keys` are the entry's indented YAML lines under `- type: <type>`
// in sensor.yaml, so files the keys name are relative to that folder and
// errors are located in sensor.yaml.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include "ConfigNode.h"
#include "support/TempDir.h"
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

}  // namespace tofsim::test
