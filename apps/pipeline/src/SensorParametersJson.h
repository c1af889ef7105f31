#pragma once
// Private to the pipeline: a sensor's parameters as JSON numbers in SI units,
// each name carrying its unit (bin_width_s, frequencies_Hz), for the metadata
// beside its outputs. The config's own keys and unit strings ("100 ps") are in
// config.effective.yaml; these are for programs.

#include <nlohmann/json.hpp>

#include "TimeAxisJson.h"
#include "tofsim/sensors/SensorSpec.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::pipeline {

/// Every parameter of the model, defaults filled in. `render` resolves the
/// instrument bins (their unset parts follow the render's axis).
nlohmann::ordered_json sensorParametersJson(const sensors::SensorParams& params,
                                            const TimeAxis& render);

}  // namespace tofsim::pipeline
