#pragma once
// Private to the config module: a SPAD's `irf:` mapping (file, bin_width,
// t0, floor), its file read into sensors::SpadIrf. Relative paths resolve
// against the config file's folder; every bad file (missing, unreadable,
// wrong columns, negative values, no area above the floor) is an InputError
// located at the key, naming the IRF file and its line.

#include <yaml-cpp/yaml.h>

#include "ConfigNode.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::config {

/// Parses `irf` (a mapping) and reads its file.
sensors::SpadIrf parseIrf(const ConfigNode& irf);

/// Writes it back as parseIrf reads it (the file as an absolute path).
YAML::Node irfToYaml(const sensors::SpadIrf& irf);

}  // namespace tofsim::config
