#pragma once
// Writes what a sensor model produced, each output by its kind
// (sensors/README.md, "Outputs"): Array -> <name>.npy, Image -> <name>.exr,
// ColorMappedImage and HistogramPlot -> <name>.png. Every file is written
// atomically.

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/sensors/SensorOutput.h"

namespace tofsim::pipeline {

/// Creates `directory` and writes every output into it. Returns the file
/// names written, in output order.
std::vector<std::string> writeSensorOutputs(const std::filesystem::path& directory,
                                            const std::vector<sensors::SensorOutput>& outputs);

}  // namespace tofsim::pipeline
