#pragma once
// Private to the pipeline: a render's record, its last files: the effective
// config and, for a batch's run, the manifest.

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/RenderRun.h"

namespace tofsim::pipeline {

/// config.effective.yaml and, with options.batchManifest, manifest.json
/// listing `files` and itself last; both added to `files`.
void writeRecord(const config::RunConfig& config, const RunOptions& options,
                 const std::filesystem::path& dir, std::vector<std::string>& files);
/// The same with the camera the job used (a glTF camera's pose, not the
/// config's defaults).
void writeRecord(const config::RunConfig& config, const capture::RenderJob& job,
                 const RunOptions& options, const std::filesystem::path& dir,
                 std::vector<std::string>& files);

}  // namespace tofsim::pipeline
