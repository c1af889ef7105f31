#pragma once
// `tofsim render` of a config with an `nlos:` section: the scan rendered
// (NlosRender.h) and written as H.npy with H.json, the grids, and
// capture.hdf5 in y-tal's layout, through the same staged folder as a camera
// render (nothing half-written on failure).

#include "tofsim/pipeline/RenderRun.h"

namespace tofsim::pipeline {

/// The scene loaded and the renderer made by `prepared` (kept for its next
/// render: a batch's worker).
RunSummary runNlosRender(const config::RunConfig& config, PreparedRenderer& prepared,
                         const RunOptions& options);

}  // namespace tofsim::pipeline
