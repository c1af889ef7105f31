#pragma once
// One render run: config -> scene -> transient renderer -> files in the
// output directory. The library function behind `tofsim render`.

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/gl/Context.h"

namespace tofsim::pipeline {

struct RunOptions {
  std::filesystem::path outputDirectory;  ///< empty: the config's output.directory
  bool quiet = false;
  gl::EglPlatform eglPlatform = gl::EglPlatform::Auto;
};

struct RunSummary {
  std::filesystem::path outputDirectory;
  capture::RenderResult result;
  std::vector<std::string> files;  ///< written, relative to outputDirectory
  std::string device;              ///< the GL renderer's description
};

RunSummary runRender(const config::RunConfig& config, const RunOptions& options);

}  // namespace tofsim::pipeline
