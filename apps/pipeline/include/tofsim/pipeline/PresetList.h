#pragma once
// `tofsim presets`: every device preset (SPAD, CW-ToF, lidar) as text, with the
// values it sets (SI units, the sensor JSON's keys) and each value's source,
// or why it is assumed; so a user can choose one without provoking an error.

#include <string>

namespace tofsim::pipeline {

/// All presets; `name` non-empty: that one only (InputError if there is none).
std::string describePresets(const std::string& name = "");

}  // namespace tofsim::pipeline
