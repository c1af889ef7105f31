#pragma once
// `tofsim render` of a config with a `sequence:` section: the scene's glTF
// animations played, one frame per frame time, the scene and the renderer
// prepared once, each frame a capture of the capture loop (CaptureLoop.h).
// The sequence is one result, staged and swapped in whole
// (StagedFolder on OUTDIR): each frame is rendered as a render's outputs
// into OUTDIR/.tofsim-sequence-partial/frame_NNNNN/ (committed there when
// complete), and when all are done they are hard-linked into the staged set
// as frame_NNNNN/, beside OUTDIR/sequence.json (the frames, their times,
// seeds and folders), depth_sequence.npy (F, H, W) with output.depth,
// sequence.mp4 and config.effective.yaml. A frame whose frame.json records
// the same run key and time (in the partial folder, or in the earlier set)
// is kept: a rerun after an interrupt resumes at its first missing frame,
// and the earlier set stays whole until the new one replaces it.

#include <filesystem>

#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/RenderRun.h"
#include "tofsim/scene/AnimatedScene.h"

namespace tofsim::pipeline {

/// Its renderer from `prepared` (kept for its next render: a batch's worker);
/// the animated scene is the sequence's own.
RunSummary runSequenceRender(const config::RunConfig& config, PreparedRenderer& prepared,
                             const RunOptions& options);

/// Frame k's seed: render.seed for frame 0 (a one-frame sequence of a still
/// scene is the static render's bytes), a distinct stream for the others.
uint64_t sequenceFrameSeed(uint64_t seed, std::size_t frame);

/// Throws InputError at `sequence` when the scene has no animation, or a
/// frame time lies outside its animations (a channel would hold its last
/// key there: frames repeating one pose).
void checkFrameTimes(const config::SequenceConfig& seq, const scene::AnimatedScene& scene,
                     const std::filesystem::path& sceneFile);

}  // namespace tofsim::pipeline
