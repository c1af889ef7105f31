#pragma once
// Runs any configured sensor model on a volume, or opens it to be fed the
// volume as it streams (SensorStream.h): runSensor is openSensor fed the whole
// volume as one span, so both give the same bytes.

#include <memory>
#include <string>
#include <vector>

#include "tofsim/sensors/SensorInputs.h"
#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/sensors/SensorSpec.h"
#include "tofsim/sensors/SensorStream.h"

namespace tofsim::sensors {

/// Throws InputError when the spec does not fit the inputs (channel out of
/// range, rows outside the image, ...).
std::vector<SensorOutput> runSensor(const SensorSpec& spec, const SensorInputs& inputs);

/// The model to feed span by span (SensorType<>::open); throws InputError
/// when the spec does not fit the shape.
std::unique_ptr<SensorStream> openSensor(const SensorSpec& spec, const VolumeShape& shape,
                                         const StreamOptions& options);

/// The model's warnings about these inputs (SensorType<>::warnings), one line each.
std::vector<std::string> sensorWarnings(const SensorSpec& spec, const SensorInputs& inputs);
/// The same for a render's shape (image, time axis) and ground-truth depth
/// (nullptr when none).
std::vector<std::string> sensorWarnings(const SensorSpec& spec, const VolumeShape& shape,
                                        const Image* groundTruthDepth_m);

}  // namespace tofsim::sensors
