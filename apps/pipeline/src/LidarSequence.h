#pragma once
// Private to the pipeline: `tofsim render` of a `lidar:` with `sequence:`
// (issue 43, rolling scans). Frame k is the lidar's turn that starts at the
// sequence's time t_k: each azimuth column fires at its own time (t_k +
// (azimuth - start) / 360 / rotation_rate, RollingScan.h) and is traced
// against the scene there (its glTF animations played, the moving meshes
// re-baked and updated in the rays' BVH per column: AnimatedWaveformScene). The frames are written as a
// lidar render's files into OUTDIR/frame_NNNNN/, beside OUTDIR/sequence.json
// (each frame's time, seed and folder) and config.effective.yaml; the whole
// set is staged and swapped in at once (no resume of an interrupted set).

#include "tofsim/pipeline/RenderRun.h"

namespace tofsim::pipeline {

RunSummary runLidarSequence(const config::RunConfig& config, const RunOptions& options);

}  // namespace tofsim::pipeline
