#pragma once
// The effective config in two parts, for a batch's content key split into
// render and sense (pipeline/RunContentKey.h): everything a render's volume
// and files depend on (the effective config without `sensors:`) and the
// sensors alone (`sensors:` as the effective config writes it).

#include <string>

#include "tofsim/config/RunConfig.h"

namespace tofsim::config {

struct EffectiveConfigParts {
  std::string render;   ///< effectiveConfigYaml of the config with no sensors
  std::string sensors;  ///< the effective `sensors:` list as YAML
};

EffectiveConfigParts effectiveConfigParts(const RunConfig& config);

}  // namespace tofsim::config
