#pragma once
// Runs any configured sensor model on a volume.

#include <string>
#include <vector>

#include "tofsim/sensors/SensorInputs.h"
#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/sensors/SensorSpec.h"

namespace tofsim::sensors {

/// Throws InputError when the spec does not fit the inputs (channel out of
/// range, rows outside the image, ...).
std::vector<SensorOutput> runSensor(const SensorSpec& spec, const SensorInputs& inputs);

/// The model's warnings about these inputs (SensorType<>::warnings), one line each.
std::vector<std::string> sensorWarnings(const SensorSpec& spec, const SensorInputs& inputs);

}  // namespace tofsim::sensors
