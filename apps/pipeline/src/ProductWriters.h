#pragma once
// Private to the pipeline: the files a render writes from what it gave, after
// its last segment (its Writer::Volume files were streamed while it ran): the
// steady image, the depth, the frames, the video and transient.json.

#include <filesystem>

#include "CaptureFile.h"
#include "OutputStreams.h"
#include "tofsim/capture/RenderJob.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/imaging/Pictures.h"
#include "tofsim/pipeline/OutputProducts.h"
#include "tofsim/pipeline/PlotRanges.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/RenderRun.h"

namespace tofsim::pipeline {

/// Writes product `p` into the staging folder `dir` (and into capture.h5
/// when `streams` has one); `summary`: the render's result, backend and device.
void writeProduct(const OutputProduct& p, const config::RunConfig& config,
                  const capture::RenderJob& job, const std::filesystem::path& dir,
                  const Image& steady, const RunSummary& summary, OutputStreams& streams,
                  PlotRanges& ranges, const Progress& progress);

}  // namespace tofsim::pipeline
