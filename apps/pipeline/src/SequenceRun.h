#pragma once
// `tofsim render` of a config with a `sequence:` section: the scene's glTF
// animations played, one frame per frame time, each written as a render's
// outputs in OUTDIR/frame_NNNNN/ (staged, committed when complete), the
// scene and the renderer prepared once. A frame folder whose frame.json
// records the same run key and time is kept: an interrupted sequence resumes
// at its first missing frame. Then OUTDIR/sequence.json (the frames, their
// times, seeds and folders), depth_sequence.npy (F, H, W) with
// output.depth, and config.effective.yaml.

#include "tofsim/pipeline/RenderRun.h"

namespace tofsim::pipeline {

RunSummary runSequenceRender(const config::RunConfig& config, const RunOptions& options);

/// Frame k's seed: render.seed for frame 0 (a one-frame sequence of a still
/// scene is the static render's bytes), a distinct stream for the others.
uint64_t sequenceFrameSeed(uint64_t seed, std::size_t frame);

}  // namespace tofsim::pipeline
