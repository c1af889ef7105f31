#pragma once
// Private to the pipeline: a capture sequence's video (SequenceRun.cpp),
// sequence.mp4: the frames' steady images in order, tone-mapped with one
// scale for them all (output.video_tone_map) and stamped with their scene
// times, at the sequence's frame rate. And the video options of the output
// keys, which transient.mp4 (RenderRun.cpp) shares.

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/imaging/Video.h"
#include "tofsim/pipeline/Progress.h"

namespace tofsim::pipeline {

/// The output keys' video options (video_tone_map, video_stride,
/// video_window, video_fps): transient.mp4's, and sequence.mp4's tone map.
imaging::VideoOptions videoOptions(const config::OutputConfig& out);

/// `steadyFiles`: frame k's steady.exr; `times_s`: frame k's time.
void writeSequenceVideo(const std::filesystem::path& mp4, const config::OutputConfig& out,
                        const std::vector<std::filesystem::path>& steadyFiles,
                        const std::vector<double>& times_s, const Progress& progress);

}  // namespace tofsim::pipeline
