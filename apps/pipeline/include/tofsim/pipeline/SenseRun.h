#pragma once
// `tofsim sense`: the configured sensors (config.sensors) run on a saved
// render, streamed from its files a run of pixels at a time (never held
// whole), their outputs written to OUTDIR/sensors/<sensor name>/.
//
// Randomness: every sensor is seeded with config.render.seed, so the same
// volume, config and seed give the same bytes whether the sensors run right
// after the render or later from its saved files.

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/PsfPath.h"
#include "tofsim/pipeline/SavedVolume.h"

namespace tofsim::pipeline {

/// Runs each sensor on the saved volume, read a run of pixels at a time
/// (runs of every saved file read together within render.memory_budget
/// bytes), and writes its outputs. `components`: "direct" (when saved), then
/// the bounces 1..N a cwtof sensor with multipath_by_order takes (the names
/// of their files, e.g. "bounce2"; see runSense). Returns the files written, relative to
/// outputDirectory ("sensors/spad/spad_counts.npy", ...). A sensor that does
/// not fit the volume (a row outside the image, ...) throws an InputError
/// naming the config file and the sensor; so does a sensor window that drops
/// light under --strict, after the last run. `psf`: PsfPath::Raws when the
/// volume is the light before the config's camera.psf, which the CW-ToF
/// sensors then apply to their raws as the render did (SharedRender.h).
std::vector<std::string> runConfiguredSensors(const config::RunConfig& config,
                                              SavedVolumeStream& saved,
                                              const std::vector<std::string>& components,
                                              const std::filesystem::path& outputDirectory,
                                              const Progress& progress,
                                              PsfPath psf = PsfPath::None);

struct SenseOptions {
  std::filesystem::path volumeDirectory;  ///< holds transient.npy and transient.json
  std::filesystem::path outputDirectory;  ///< empty: volumeDirectory
  bool quiet = false;
};

struct SenseSummary {
  std::filesystem::path outputDirectory;
  std::vector<std::string> files;  ///< relative to outputDirectory
  double seconds = 0.0;
};

/// `tofsim sense`: opens a saved render (SavedVolumeStream) and runs the
/// config's sensors on it. Uses only the config's `sensors:` and `render.seed`; the
/// sensors take the time axis and image size from the saved volume.
/// A cwtof sensor with multipath_by_order takes the render's N from
/// transient.json (`indirect_bounces`) and needs direct.npy, bounce1.npy ..
/// bounce<N>.npy (for N = 1 indirect.npy will do) and depth.exr: an
/// InputError names the first file missing.
SenseSummary runSense(const config::RunConfig& config, const SenseOptions& options);

}  // namespace tofsim::pipeline
