#include "tofsim/pipeline/SenseRun.h"

#include <chrono>
#include <cstdio>

#include "tofsim/pipeline/AxisReport.h"
#include "tofsim/pipeline/PlotRanges.h"
#include "tofsim/pipeline/SavedVolume.h"
#include "tofsim/pipeline/SensorStreams.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"
#include "tofsim/util/StagedFolder.h"

namespace tofsim::pipeline {

void warnUntakenPlotRanges(const std::vector<std::string>& keys) {
  for (const std::string& key : keys) {
    std::fprintf(stderr, "tofsim: warning: output.plot_ranges.%s names no picture of this run\n",
                 key.c_str());
  }
}

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The config says what it expects; the saved volume decides. A mismatch is
// legitimate (a volume rendered with other --set values) but worth a note.
void noteDifferences(const config::RunConfig& config, const TransientVolume& volume,
                     const Progress& progress) {
  const capture::Camera& cam = config.camera.camera;
  const TimeAxis& axis = config.render.time;
  if (cam.width != volume.width() || cam.height != volume.height() || axis.bins != volume.bins() ||
      axis.start_s != volume.axis().start_s || axis.bin_width_s != volume.axis().bin_width_s ||
      axis.index_of_refraction != volume.axis().index_of_refraction ||
      axis.camera_unwarp != volume.axis().camera_unwarp) {
    progress.message(
        "note: the saved volume's size or time axis differs from the config's; "
        "the sensors use the volume's");
  }
}

// The light by bounce order of a saved render, for a cwtof sensor with
// multipath_by_order: N from transient.json, then bounce1 .. bounce<N>.npy.
std::vector<TransientVolume> savedBounces(const config::RunConfig& config,
                                          const std::filesystem::path& dir,
                                          const SavedVolume& saved) {
  const auto fail = [&](const std::filesystem::path& file, const std::string& why) {
    throw InputError(FileLoc{file.string()}, "",
                     why + ": a cwtof sensor with multipath_by_order (" +
                         config.config_file.string() +
                         ") needs the render's direct.npy, bounce<k>.npy and depth.exr");
  };
  if (!saved.directOnly) fail(dir / "direct.npy", "not found");
  if (!saved.depth_m) fail(dir / "depth.exr", "not found");
  const int32_t n = savedIndirectBounces(dir / "transient.json");
  std::vector<TransientVolume> bounces;
  for (int32_t k = 1; k <= n; ++k) {
    std::optional<TransientVolume> b = loadSavedComponent(dir, "bounce" + std::to_string(k));
    if (!b && n == 1) b = loadSavedComponent(dir, "indirect");  // one bounce: the same light
    if (!b) {
      fail(dir / ("bounce" + std::to_string(k) + ".npy"),
           "not found (transient.json: indirect_bounces " + std::to_string(n) +
               "; render with output.components: [direct, bounce1 .. bounce" + std::to_string(n) +
               "])");
    }
    bounces.push_back(std::move(*b));
  }
  return bounces;
}

}  // namespace

std::vector<std::string> runConfiguredSensors(const config::RunConfig& config,
                                              const SensorVolumes& volumes,
                                              const std::filesystem::path& outputDirectory,
                                              const Progress& progress) {
  TOFSIM_CHECK(volumes.volume != nullptr);
  const TransientVolume& volume = *volumes.volume;
  if (const TransientVolume* d = volumes.directOnly) {
    TOFSIM_CHECK(d->width() == volume.width() && d->height() == volume.height() &&
                 d->bins() == volume.bins() && d->channels() == volume.channels());
  }
  // The whole volume as one span: the same code, and so the same bytes, as a
  // render's sensors fed segment by segment.
  std::optional<int32_t> bounces;
  if (volumes.bounces) {
    TOFSIM_CHECK(volumes.directOnly != nullptr);
    bounces = static_cast<int32_t>(volumes.bounces->size());
  }
  SensorStreams streams(config, sensors::shapeOf(volume), volumes.directOnly != nullptr, bounces,
                        outputDirectory);
  streams.consume(sensors::wholeVolume(volume, volumes.directOnly, volumes.bounces));
  return streams.finish(volumes.depth_m, progress);
}

SenseSummary runSense(const config::RunConfig& config, const SenseOptions& options) {
  if (config.sensors.empty()) {
    throw InputError(FileLoc{config.config_file.string()}, "sensors",
                     "the config lists no sensors: nothing to simulate");
  }
  const auto start = std::chrono::steady_clock::now();
  Progress progress("sense", options.quiet);
  const SavedVolume saved = loadSavedVolume(options.volumeDirectory);
  noteDifferences(config, saved.volume, progress);
  checkSensorWindows(config, saved.volume);  // before any file; throws under --strict
  SenseSummary summary;
  summary.outputDirectory =
      options.outputDirectory.empty() ? options.volumeDirectory : options.outputDirectory;
  SensorVolumes volumes;
  volumes.volume = &saved.volume;
  volumes.directOnly = saved.directOnly ? &*saved.directOnly : nullptr;
  volumes.depth_m = saved.depth_m ? &*saved.depth_m : nullptr;
  std::vector<TransientVolume> bounces;
  if (sensorBounces(config)) bounces = savedBounces(config, options.volumeDirectory, saved);
  std::vector<const TransientVolume*> bouncePointers;
  for (const TransientVolume& b : bounces) bouncePointers.push_back(&b);
  if (sensorBounces(config)) volumes.bounces = &bouncePointers;
  // The folder's other files (the render's) stay; its sensors/ is replaced as
  // a whole, atomically, so sensors no longer configured go and an interrupted
  // run leaves the earlier sensors/. A batch manifest no longer describes the
  // folder once its sensors change, so it goes too (the run is redone).
  StagedFolder folder(summary.outputDirectory, [](const std::string& name) {
    return name != "sensors" && name != "manifest.json";
  });
  summary.files = runConfiguredSensors(config, volumes, folder.staging(), progress);
  throwIfInterrupted();
  folder.commit();
  summary.seconds = secondsSince(start);
  return summary;
}

}  // namespace tofsim::pipeline
