#pragma once
// `tofsim render` of a config with a `lidar:` section (issue 43): the
// beams' waveforms from direct light (core/lidar), their returns, and the
// files (LidarFiles.h), through the same staged folder as a camera render
// (nothing half-written on failure).

#include "tofsim/lidar/MultipathSettings.h"
#include "tofsim/pipeline/OutputEstimate.h"
#include "tofsim/pipeline/RenderRun.h"

namespace tofsim::pipeline {

/// The scene loaded by `prepared` (kept for its next render: a batch's
/// worker); rays traced on render.threads threads.
RunSummary runLidarRender(const config::RunConfig& config, PreparedRenderer& prepared,
                          const RunOptions& options);

/// lidar.multipath with the render's clamps, materials and seed (off unless
/// asked for): a still frame's and a rolling frame's.
lidar::MultipathSettings lidarMultipath(const config::RunConfig& config);

/// The files a lidar run writes and their sizes, from the config alone.
OutputEstimate lidarOutputs(const config::RunConfig& config);

}  // namespace tofsim::pipeline
