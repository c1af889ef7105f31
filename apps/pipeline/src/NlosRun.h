#pragma once
// `tofsim render` of a config with an `nlos:` section: the scan rendered
// (NlosRender.h) and written as H.npy with H.json, the grids, and
// capture.hdf5 in y-tal's layout, through the same staged folder as a camera
// render (nothing half-written on failure).

#include "tofsim/pipeline/RenderRun.h"

namespace tofsim::pipeline {

RunSummary runNlosRender(const config::RunConfig& config, const RunOptions& options);

}  // namespace tofsim::pipeline
