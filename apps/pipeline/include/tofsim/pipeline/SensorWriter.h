#pragma once
// Writes what a sensor model produced, each output by its kind
// (sensors/README.md, "Outputs"): Array -> <name>.npy, Image -> <name>.exr,
// ColorMappedImage and HistogramPlot -> <name>.png; and for every name its
// metadata, <name>.json (SensorMetadata.h). Every file is written atomically.

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/pipeline/PlotRanges.h"
#include "tofsim/pipeline/SensorMetadata.h"
#include "tofsim/sensors/SensorOutput.h"

namespace tofsim::pipeline {

/// Creates `directory` and writes every output into it, then the metadata of
/// each name. Pictures take their fixed colour range from `ranges` under
/// "sensors/<sensor>/<output>". Returns the file names written, in that order.
std::vector<std::string> writeSensorOutputs(const std::filesystem::path& directory,
                                            const std::vector<sensors::SensorOutput>& outputs,
                                            const SensorRunInfo& run, PlotRanges& ranges);

}  // namespace tofsim::pipeline
