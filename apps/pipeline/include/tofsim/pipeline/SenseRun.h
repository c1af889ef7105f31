#pragma once
// The configured sensors (config.sensors) run on a transient volume, their
// outputs written to OUTDIR/sensors/<sensor name>/. Used after a render by
// `tofsim render`, and on a saved render by `tofsim sense`.
//
// Randomness: every sensor is seeded with config.render.seed, so the same
// volume, config and seed give the same bytes whether the sensors run right
// after the render or later from its saved files.

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::pipeline {

/// What the sensors see. Only `volume` is required; `directOnly` and
/// `depth_m` feed the CW-ToF multipath-error outputs.
struct SensorVolumes {
  const TransientVolume* volume = nullptr;
  const TransientVolume* directOnly = nullptr;
  const Image* depth_m = nullptr;  ///< (H, W, 1), metres
  /// Bounces 1..N, with directOnly, for the CW-ToF error by bounce order.
  const std::vector<const TransientVolume*>* bounces = nullptr;
};

/// Runs each sensor in order and writes its outputs. Returns the files written,
/// relative to outputDirectory ("sensors/spad/spad_counts.npy", ...). A sensor
/// that does not fit the volume (a row outside the image, ...) throws an
/// InputError naming the config file and the sensor.
std::vector<std::string> runConfiguredSensors(const config::RunConfig& config,
                                              const SensorVolumes& volumes,
                                              const std::filesystem::path& outputDirectory,
                                              const Progress& progress);

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

/// `tofsim sense`: loads a saved render (SavedVolume.h) and runs the config's
/// sensors on it. Uses only the config's `sensors:` and `render.seed`; the
/// sensors take the time axis and image size from the saved volume. A cwtof
/// sensor with multipath_by_order takes the render's N from transient.json
/// (`indirect_bounces`) and needs direct.npy, bounce1.npy .. bounce<N>.npy
/// (for N = 1 indirect.npy will do) and depth.exr: an InputError names the
/// first file missing.
SenseSummary runSense(const config::RunConfig& config, const SenseOptions& options);

}  // namespace tofsim::pipeline
