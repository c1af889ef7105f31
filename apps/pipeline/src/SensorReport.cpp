#include "SensorReport.h"

#include <cstdio>

#include "Warning.h"
#include "tofsim/sensors/SensorSpec.h"

namespace tofsim::pipeline {

void rethrowSensorError(const config::RunConfig& config, std::size_t i, const InputError& e) {
  const sensors::SensorSpec& spec = config.sensors[i];
  throw InputError(
      FileLoc{config.config_file.string()}, "sensors[" + std::to_string(i) + "]",
      "sensor '" + spec.name + "' (" + sensors::sensorTypeName(spec.params) + "): " + e.what());
}

void printSensorWarnings(const sensors::SensorSpec& spec,
                         const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) {
    warn("sensor '" + spec.name + "' (" + sensors::sensorTypeName(spec.params) + "): " + w);
  }
}

}  // namespace tofsim::pipeline
