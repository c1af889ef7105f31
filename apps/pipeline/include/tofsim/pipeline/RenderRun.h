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
  std::string renderFrom;  ///< the run whose render it took (SharedRender.h); "" itself
};

struct RunOptions {
  std::filesystem::path outputDirectory;  ///< empty: the config's output.directory
  bool quiet = false;
  gl::EglPlatform eglPlatform = gl::EglPlatform::Auto;
  std::optional<BatchManifestInfo> batchManifest;  ///< set by `tofsim render --batch-run`
  /// Internal: camera.psf on the transient even where the CW-ToF raws would
  /// do (PsfPath.h), so that the tests can compare the two paths.
  bool psfOnTransient = false;
  /// Internal, for `tofsim batch` (SharedRender.h): a folder where a render
  /// that saves no transient.npy of its own also saves the volume its
  /// sensors see (transient.npy and transient.json: the light before a
  /// camera.psf applied on the raws), for the runs that take its render.
  /// Empty: none.
  std::filesystem::path sharedVolume;
};

struct RunSummary {
  std::filesystem::path outputDirectory;
  capture::RenderResult result;
  std::vector<std::string> files;  ///< written, relative to outputDirectory
  std::string backend;             ///< "gl" or "cpu" (render.backend, auto decided), or "reference"
  std::string
      device;  ///< the renderer's device, e.g. "llvmpipe (LLVM 15...)" or "CPU (2 threads, Embree)"
};

class PreparedRenderer;

RunSummary runRender(const config::RunConfig& config, const RunOptions& options);
/// The same through a renderer that stays loaded (PreparedRenderer.h): its
/// scene and renderer kept where the config allows, loaded or made again
/// where it does not; the files are those of a render of its own. NLOS
/// configs load their scene there too; sequence configs take its renderer
/// and play their own animated scene. Every capture (one, a scan's laser
/// positions, a sequence's frames) goes through the capture loop
/// (CaptureLoop.h).
RunSummary runRender(const config::RunConfig& config, PreparedRenderer& prepared,
                     const RunOptions& options);
/// The same over a scene already loaded (or built in code by a test) in
/// place of config.scene_file's; not for NLOS configs.
RunSummary runRender(const config::RunConfig& config, const scene::Scene& scene,
                     const RunOptions& options);

/// What `tofsim render` says at its end: "render: 0.42 s, 3 segment(s); wrote
/// 9 file(s) to out" and, with adaptive pixel samples, how many pixels took
/// them (lines ending in a newline).
std::string renderSummaryText(const config::RunConfig& config, const RunSummary& summary);

}  // namespace tofsim::pipeline
