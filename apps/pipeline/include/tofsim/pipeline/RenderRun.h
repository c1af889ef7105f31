#pragma once
// One render run: config -> scene -> transient renderer -> files in the
// output directory. The library function behind `tofsim render`.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/gl/Context.h"
#include "tofsim/pipeline/RunContentKey.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::pipeline {

/// A render started by `tofsim batch` writes the run's manifest.json
/// (Manifest.h) as the last file of its output set.
struct BatchManifestInfo {
  std::string runName;
  RunContentKey inputs;
};

struct RunOptions {
  std::filesystem::path outputDirectory;  ///< empty: the config's output.directory
  bool quiet = false;
  gl::EglPlatform eglPlatform = gl::EglPlatform::Auto;
  std::optional<BatchManifestInfo> batchManifest;  ///< set by `tofsim render --batch-run`
  /// Internal: camera.psf on the transient even where the CW-ToF raws would
  /// do (PsfPath.h), so that the tests can compare the two paths.
  bool psfOnTransient = false;
};

struct RunSummary {
  std::filesystem::path outputDirectory;
  capture::RenderResult result;
  std::vector<std::string> files;  ///< written, relative to outputDirectory
  std::string backend;             ///< "gl" or "cpu" (render.backend, auto decided), or "reference"
  std::string
      device;  ///< the renderer's device, e.g. "llvmpipe (LLVM 15...)" or "CPU (2 threads, Embree)"
};

RunSummary runRender(const config::RunConfig& config, const RunOptions& options);
/// The same over a scene already loaded (or built in code by a test) in
/// place of config.scene_file's; not for NLOS configs.
RunSummary runRender(const config::RunConfig& config, const scene::Scene& scene,
                     const RunOptions& options);

}  // namespace tofsim::pipeline
