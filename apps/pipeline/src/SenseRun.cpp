#include "tofsim/pipeline/SenseRun.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <variant>

#include "StagedOutput.h"
#include "Warning.h"
#include "tofsim/pipeline/Capture.h"
#include "tofsim/pipeline/OutputProducts.h"
#include "tofsim/pipeline/PlotRanges.h"
#include "tofsim/pipeline/SavedVolume.h"
#include "tofsim/pipeline/SensorStreams.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/sensors/SensorType.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

void warnUntakenPlotRanges(const std::vector<std::string>& keys) {
  for (const std::string& key : keys) {
    warn("output.plot_ranges." + key + " names no picture of this run");
  }
}

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The config says what it expects; the saved volume decides. A mismatch is
// legitimate (a volume rendered with other --set values) but worth a note.
void noteDifferences(const config::RunConfig& config, const sensors::VolumeShape& volume,
                     const Progress& progress) {
  const capture::Camera& cam = config.camera.camera;
  const TimeAxis& axis = config.render.time;
  if (cam.width != volume.width || cam.height != volume.height || axis.bins != volume.axis.bins ||
      axis.start_s != volume.axis.start_s || axis.bin_width_s != volume.axis.bin_width_s ||
      axis.index_of_refraction != volume.axis.index_of_refraction ||
      axis.camera_unwarp != volume.axis.camera_unwarp) {
    progress.message(
        "note: the saved volume's size or time axis differs from the config's; "
        "the sensors use the volume's");
  }
}

// The saved components the sensors take beside the total: the direct light,
// and for a cwtof sensor with multipath_by_order the light by bounce order,
// bounce1 .. bounce<N> with N from transient.json (indirect.npy stands for
// bounce1 when N = 1: the same light). An InputError names the first file
// missing. Each is its .npy, or the dataset of the folder's capture.h5.
std::vector<std::string> sensedComponents(const config::RunConfig& config,
                                          const std::filesystem::path& dir) {
  std::vector<std::string> components = {"direct"};
  if (!sensorBounces(config)) return components;
  const auto fail = [&](const std::filesystem::path& file, const std::string& why) {
    throw InputError(FileLoc{file.string()}, "",
                     why + ": a cwtof sensor with multipath_by_order (" +
                         config.config_file.string() +
                         ") needs the render's direct.npy, bounce<k>.npy and depth.exr");
  };
  if (!hasSavedComponent(dir, "direct")) fail(savedComponentName(dir, "direct"), "not found");
  if (!std::filesystem::exists(dir / files::kDepthExr)) fail(dir / files::kDepthExr, "not found");
  const int32_t n = savedIndirectBounces(dir / files::kMetadata);
  for (int32_t k = 1; k <= n; ++k) {
    const std::string name = "bounce" + std::to_string(k);
    if (hasSavedComponent(dir, name)) {
      components.push_back(name);
    } else if (n == 1 && hasSavedComponent(dir, "indirect")) {
      components.push_back("indirect");
    } else {
      fail(savedComponentName(dir, name),
           "not found (transient.json: indirect_bounces " + std::to_string(n) +
               "; render with output.components: [direct, bounce1 .. bounce" + std::to_string(n) +
               "])");
    }
  }
  return components;
}

// Pixels per run read: the files' runs together within render.memory_budget.
std::size_t pixelsPerRun(const config::RunConfig& config, const SavedVolumeStream& saved,
                         const std::vector<std::string>& components) {
  std::size_t files = 1;
  for (const std::string& c : components) files += saved.has(c) ? 1 : 0;
  const std::size_t pixelBytes = saved.shape().pixelFloats() * sizeof(float) * files;
  return std::max<std::size_t>(1, config.render.memory_budget_bytes / pixelBytes);
}

// The pinhole the saved pixels looked through, for the point clouds, as the
// render had it: the config's camera or the glTF camera it names (the scene
// is read for its pose). None for a volume of another size, or when the
// scene cannot be read (a note: the other outputs do not need it).
std::optional<capture::Camera> senseCamera(const config::RunConfig& config,
                                           const sensors::VolumeShape& volume,
                                           const Progress& progress) {
  if (config.nlos) return std::nullopt;  // wall points, not a pinhole's pixels
  capture::Camera camera = config.camera.camera;
  if (camera.width != volume.width || camera.height != volume.height) return std::nullopt;
  if (config.camera.gltf_camera.empty()) return camera;
  try {
    const scene::Scene scene = scene::loadGltf(config.scene_file);
    return makeRenderJob(config, scene).camera();
  } catch (const InputError& e) {
    progress.message(std::string("note: no point clouds (the camera's pose): ") + e.what());
    return std::nullopt;
  }
}

// The sensors' blur kernels on the saved volume's axis, which may not be the
// config's the loader checked (checkSensorKernels): refused before anything
// is staged.
void checkKernelsOnVolume(const config::RunConfig& config, const TimeAxis& axis) {
  for (std::size_t i = 0; i < config.sensors.size(); ++i) {
    const std::vector<sensors::TimeKernelUse> kernels = std::visit(
        [&](const auto& p) {
          return sensors::SensorType<std::decay_t<decltype(p)>>::timeKernels(p, axis);
        },
        config.sensors[i].params);
    for (const sensors::TimeKernelUse& k : kernels) {
      const std::string problem = sensors::timeKernelProblem(k);
      if (problem.empty()) continue;
      throw InputError(FileLoc{config.config_file.string()},
                       "sensors[" + std::to_string(i) + "]." + k.key,
                       problem + " on the saved volume's time axis");
    }
  }
}

}  // namespace

std::vector<std::string> runConfiguredSensors(const config::RunConfig& config,
                                              SavedVolumeStream& saved,
                                              const std::vector<std::string>& components,
                                              const std::filesystem::path& outputDirectory,
                                              const Progress& progress, PsfPath psf) {
  // Run by run, as a render's sensors are fed segment by segment: the same
  // code, and so the same bytes (the per-pixel random streams do not see
  // where the runs are cut).
  const bool withDirect = saved.has("direct");
  // components[1..]: the bounces, when a sensor asked for them.
  std::optional<int32_t> bounces;
  if (sensorBounces(config)) bounces = static_cast<int32_t>(components.size()) - 1;
  const std::optional<capture::Camera> camera = senseCamera(config, saved.shape(), progress);
  SensorStreams streams(config, saved.shape(), withDirect, bounces, outputDirectory,
                        camera ? &*camera : nullptr, psf);
  const std::size_t run = pixelsPerRun(config, saved, components);
  while (const std::size_t pixels = saved.read(run)) {
    throwIfInterrupted();
    sensors::PixelSpan span{saved.firstPixel(), pixels, saved.values("transient"),
                            withDirect ? saved.values("direct") : nullptr};
    if (bounces) {
      for (std::size_t k = 1; k < components.size(); ++k) {
        span.bounces.push_back(saved.values(components[k]));
      }
    }
    streams.consume(span);
  }
  streams.checkWindows();  // throws under --strict: the staged files go
  return streams.finish(saved.depth_m(), progress);
}

SenseSummary runSense(const config::RunConfig& config, const SenseOptions& options) {
  if (config.sensors.empty()) {
    throw InputError(FileLoc{config.config_file.string()}, "sensors",
                     "the config lists no sensors: nothing to simulate");
  }
  const auto start = std::chrono::steady_clock::now();
  Progress progress("sense", options.quiet);
  const std::vector<std::string> components = sensedComponents(config, options.volumeDirectory);
  SavedVolumeStream saved(options.volumeDirectory, components);
  noteDifferences(config, saved.shape(), progress);
  checkKernelsOnVolume(config, saved.shape().axis);
  SenseSummary summary;
  summary.outputDirectory =
      options.outputDirectory.empty() ? options.volumeDirectory : options.outputDirectory;
  // The folder's other files (the render's) stay; its sensors/ is replaced as
  // a whole, atomically, so sensors no longer configured go and an interrupted
  // or failed run leaves the earlier sensors/. A batch manifest no longer
  // describes the folder once its sensors change, so it goes too (the run is
  // redone).
  StagedFolder folder(summary.outputDirectory, [](const std::string& name) {
    return name != "sensors" && name != "manifest.json";
  });
  noteLinkedOutput(folder, progress);
  summary.files = runConfiguredSensors(config, saved, components, folder.staging(), progress);
  throwIfInterrupted();
  commitOutput(folder, progress);
  summary.seconds = secondsSince(start);
  return summary;
}

}  // namespace tofsim::pipeline
