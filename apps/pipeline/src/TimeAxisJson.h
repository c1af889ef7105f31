#pragma once
// Private to the pipeline: the one JSON form of a time axis, written into
// transient.json, H.json and every sensor output's metadata.

#include <nlohmann/json.hpp>

#include "tofsim/volume/TimeAxis.h"

namespace tofsim::pipeline {

/// {start_s, bin_width_s, bins, end_s, and the same in metres of optical path
/// and of depth}: how to turn a bin index into a time and a distance.
nlohmann::ordered_json timeAxisJson(const TimeAxis& axis);

}  // namespace tofsim::pipeline
