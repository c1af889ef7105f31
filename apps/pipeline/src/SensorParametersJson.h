#pragma once
// Private to the pipeline: a sensor's parameters as JSON numbers in SI units,
// each name carrying its unit (bin_width_s, frequencies_Hz), for the metadata
// beside its outputs. The config's own keys and unit strings ("100 ps") are in
// config.effective.yaml; these are for programs.

#include <nlohmann/json.hpp>

#include "tofsim/sensors/SensorSpec.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::pipeline {

/// Every parameter of the model, defaults filled in. `render` resolves the
/// instrument bins (their unset parts follow the render's axis).
nlohmann::ordered_json sensorParametersJson(const sensors::SensorParams& params,
                                            const TimeAxis& render);

/// {start_s, bin_width_s, bins, end_s, and the same in metres of optical path
/// and of depth}: how to turn a bin index into a time and a distance.
nlohmann::ordered_json timeAxisJson(const TimeAxis& axis);

}  // namespace tofsim::pipeline
