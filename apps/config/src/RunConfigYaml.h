#pragma once
// Private to the config module: the run-config parser on a YAML document
// already in memory, shared by loadRunConfig (a file) and loadRunConfigText
// (text handed over by the Python module).

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <vector>

#include "tofsim/config/RunConfig.h"

namespace tofsim::config {

/// Overrides, validates and converts `yaml`; `file` names it in errors and
/// anchors relative paths (the scene) at its folder.
RunConfig loadRunConfigYaml(YAML::Node yaml, const std::filesystem::path& file,
                            const std::vector<Override>& overrides);

}  // namespace tofsim::config
