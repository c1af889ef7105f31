#pragma once
// Private to the pipeline: one frame of a capture sequence (SequenceRun.cpp)
// written as a render's outputs (RenderRun.cpp's capture sink), with the renderer kept
// across the frames and the scene moved to the times the sensors sample
// within the frame (SensorStreams::passOffsets_s).

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/pipeline/CaptureLoop.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/RenderRun.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::pipeline {

struct SequenceFrame {
  /// The sequence's renderer (made once for it): its sensor passes' too.
  PreparedRenderer* prepared = nullptr;
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

/// A render's outputs as a capture loop's sink (CaptureLoop.h): the files of
/// `job`'s render in options.outputDirectory (staged, committed when the
/// sink finishes), `summary` filled in. For a sequence's frame (`frame` not
/// null): its sensor passes rendered when the sink is made, and
/// frame->record in place of the run's record (config.effective.yaml, the
/// manifest: the sequence writes them once). `config`, `job`, `options`,
/// `progress`, `summary` and `frame` must outlive the sink.
std::unique_ptr<CaptureSink> outputSink(const config::RunConfig& config,
                                        const capture::RenderJob& job, const RunOptions& options,
                                        Progress& progress, RunSummary& summary,
                                        const SequenceFrame* frame);

/// The loader's notes on what it skipped; `animationsPlayed`: a sequence
/// plays the scene's animations (no note that they are not).
void reportLoad(const scene::LoadReport& report, const Progress& progress, bool animationsPlayed);

}  // namespace tofsim::pipeline
