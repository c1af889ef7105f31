#pragma once
// The configured sensors on an NLOS capture: each sensor point is one pixel
// of an image of sx rows (lx x ly x sx for exhaustive scans) by sy columns,
// fed H plus the laser spot's first bounce, one channel. Outputs go to
// sensors/<name>/ as for a camera; a SPAD's counts also as
// sensors/<name>/capture.hdf5, the noisy H in y-tal's layout on the TDC axis.

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/NlosRender.h"
#include "tofsim/pipeline/NlosScan.h"
#include "tofsim/pipeline/Progress.h"

namespace tofsim::pipeline {

/// Returns the files written, relative to `directory`.
std::vector<std::string> runNlosSensors(const config::RunConfig& config,
                                        const NlosScanGeometry& scan, const NlosVolume& volume,
                                        const std::vector<float>& firstBounce,
                                        const std::filesystem::path& directory,
                                        const Progress& progress);

}  // namespace tofsim::pipeline
