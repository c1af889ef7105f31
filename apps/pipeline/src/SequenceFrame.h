#pragma once
// Private to the pipeline: one frame of a capture sequence (SequenceRun.cpp)
// written as a render's outputs (RenderRun.cpp), with the renderer kept
// across the frames and the scene moved to the times the sensors sample
// within the frame (SensorStreams::passOffsets_s).

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/RenderRun.h"
#include "tofsim/pipeline/RendererFactory.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::pipeline {

struct SequenceFrame {
  const RendererChoice* renderer = nullptr;  ///< made once for the sequence
  /// Moves the scene (in place) to the frame's time + offset_s and returns
  /// the render job there (prepareCapture's: its camera may move too).
  std::function<capture::RenderJob(double offset_s)> jobAt;
  /// Writes the frame's record into the staging folder `dir` as its last
  /// file, in place of the run's record, and adds it to `files`; `result`:
  /// the render at the frame's own time.
  std::function<void(const std::filesystem::path& dir, std::vector<std::string>& files,
                     const capture::RenderResult& result)>
      record;
};

/// renderScene's outputs for a frame of a sequence in options.outputDirectory
/// (staged, committed when complete), with frame.record in place of the
/// run's record (config.effective.yaml, the manifest: the sequence writes
/// them once).
RunSummary renderSequenceFrame(const config::RunConfig& config, const scene::Scene& scene,
                               const RunOptions& options, Progress& progress,
                               const SequenceFrame& frame);

/// The loader's notes on what it skipped; `animationsPlayed`: a sequence
/// plays the scene's animations (no note that they are not).
void reportLoad(const scene::LoadReport& report, const Progress& progress, bool animationsPlayed);

}  // namespace tofsim::pipeline
