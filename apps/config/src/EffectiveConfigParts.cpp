#include "tofsim/config/EffectiveConfigParts.h"

#include <yaml-cpp/yaml.h>

#include "tofsim/config/SensorConfig.h"

namespace tofsim::config {

EffectiveConfigParts effectiveConfigParts(const RunConfig& config) {
  RunConfig withoutSensors = config;
  withoutSensors.sensors.clear();
  YAML::Emitter sensors;
  sensors << sensorsToYaml(config.sensors);
  return {effectiveConfigYaml(withoutSensors), sensors.c_str()};
}

}  // namespace tofsim::config
