#pragma once
// The `sensors:` list of a config file, parsed into the sensor models' own
// parameter structs, and written back with every default filled in. Keys and
// units: sensors/README.md.

#include <string>
#include <vector>

#include "tofsim/capture/Camera.h"
#include "tofsim/sensors/SensorSpec.h"

namespace YAML {
class Node;
}

namespace tofsim::config {

class ConfigNode;

/// Parses a list of mappings, each with `type: streak | spad | cwtof` and that
/// model's keys. Throws InputError with file:line:col and the key path for bad
/// values, unknown types and unknown keys.
std::vector<sensors::SensorSpec> parseSensors(const ConfigNode& sensorsList);

/// One sensor given as YAML (or JSON) text of a mapping in the format of a
/// `sensors:` entry. Errors name `file` and the key path
/// (`sensors[0].<key>`), as parseSensors does.
sensors::SensorSpec parseSensorText(const std::string& yamlText, const std::string& file);

/// Rows and pixels the sensors name must lie in the image: a located error
/// (at sensors[i]) before the render rather than after it.
void checkSensorsFitImage(const ConfigNode& sensorsList,
                          const std::vector<sensors::SensorSpec>& specs,
                          const capture::Camera& camera);

/// Every blur kernel a sensor builds on its bins of the `render` axis must be
/// one it can lay out (sensors/SensorType.h, timeKernelProblem): a located
/// error at the key that sets it (an IRF's `file`) before the render.
void checkSensorKernels(const ConfigNode& sensorsList,
                        const std::vector<sensors::SensorSpec>& specs, const TimeAxis& render);

/// The effective configuration (defaults filled in) as a YAML sequence that
/// parseSensors reads back to the same parameters.
YAML::Node sensorsToYaml(const std::vector<sensors::SensorSpec>& specs);

}  // namespace tofsim::config
