#include "tofsim/pipeline/RenderRun.h"

#include <cstdio>
#include <optional>

#include "tofsim/imaging/Pictures.h"
#include "tofsim/imaging/Video.h"
#include "tofsim/io/DepthExr.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/AxisReport.h"
#include "tofsim/pipeline/Capture.h"
#include "tofsim/pipeline/Manifest.h"
#include "tofsim/pipeline/Metadata.h"
#include "tofsim/pipeline/OutputEstimate.h"
#include "tofsim/pipeline/OutputSink.h"
#include "tofsim/pipeline/PlotRanges.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/RendererFactory.h"
#include "tofsim/pipeline/SensorStreams.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"
#include "tofsim/util/StagedFolder.h"

namespace tofsim::pipeline {

namespace {

void reportLoad(const scene::LoadReport& report, const Progress& progress) {
  for (const std::string& w : report.warnings) progress.message("scene: " + w);
  if (report.skippedPrimitives > 0) {
    progress.message("scene: skipped " + std::to_string(report.skippedPrimitives) +
                     " point/line primitives");
  }
  if (report.emissiveMaterials + report.transmissiveMaterials > 0) {
    progress.message("scene: emissive/transmissive materials render as diffuse base colour");
  }
}

void writeFrames(const std::filesystem::path& directory, const TransientVolume& volume,
                 std::vector<std::string>& files) {
  std::filesystem::create_directories(directory / "frames");
  for (int32_t t = 0; t < volume.bins(); ++t) {
    throwIfInterrupted();
    Image frame(volume.width(), volume.height(), volume.channels());
    for (int32_t y = 0; y < volume.height(); ++y) {
      for (int32_t x = 0; x < volume.width(); ++x) {
        for (int32_t c = 0; c < volume.channels(); ++c) frame.at(y, x, c) = volume.at(y, x, t, c);
      }
    }
    char name[64];
    std::snprintf(name, sizeof name, "frames/frame_%05d.exr", t);
    io::writeExr(directory / name, frame, volume.channelNames());
    files.push_back(name);
  }
}

// transient.mp4 and/or frames/frame_NNNNN.png (the same pictures).
void writeVideo(const std::filesystem::path& dir, const config::OutputConfig& out,
                const TransientVolume& volume, const Progress& progress,
                std::vector<std::string>& files) {
  imaging::VideoOptions options;
  options.toneMap = out.video_tone_map == config::VideoToneMap::Log ? imaging::ToneMap::Log
                                                                    : imaging::ToneMap::Global;
  options.stride = out.video_stride;
  options.window = out.video_window;
  options.fps = out.video_fps;
  progress.message(
      "video: " + std::to_string(imaging::videoFrameCount(volume.bins(), out.video_stride)) +
      " frame(s)");
  imaging::writeTransientVideo(out.video ? dir / "transient.mp4" : std::filesystem::path(), volume,
                               options, out.frame_pngs ? dir / "frames" : std::filesystem::path());
  if (out.video) files.push_back("transient.mp4");
  if (out.frame_pngs) {
    for (int32_t t = 0; t < volume.bins(); t += out.video_stride) {
      char name[64];
      std::snprintf(name, sizeof name, "frames/frame_%05d.png", t);
      files.push_back(name);
    }
  }
}

}  // namespace

namespace {
void writeOutputs(const config::RunConfig& config, const capture::RenderJob& job,
                  const RunOptions& options, const std::filesystem::path& dir, Progress& progress,
                  RunSummary& summary);

// A batch's log.txt is written by the batch while this run goes: it belongs to
// the folder, not to any one set of results.
bool keepAcrossRenders(const std::string& name) { return name == "log.txt"; }
}  // namespace

RunSummary runRender(const config::RunConfig& config, const RunOptions& options) {
  Progress progress("render", options.quiet);
  scene::LoadReport report;
  const scene::Scene scene = scene::loadGltf(config.scene_file, &report);
  reportLoad(report, progress);
  const capture::RenderJob job = makeRenderJob(config, scene);
  checkAxisBeforeRender(config, job, false);  // a proven cut fails here under --strict

  RunSummary summary;
  summary.outputDirectory =
      options.outputDirectory.empty() ? config.output.directory : options.outputDirectory;
  // Checked and locked before any rendering, so that a bad -o or a second
  // writer fails in a second. Everything is written into a staging folder
  // that replaces the earlier results only when complete: an error, Ctrl-C or
  // kill -9 before that leaves the earlier set untouched.
  StagedFolder folder(summary.outputDirectory, keepAcrossRenders);
  checkOutputsFit(estimateOutputs(config), config, folder.staging());
  writeOutputs(config, job, options, folder.staging(), progress, summary);
  // A signal that came during the last step still means "stop": the earlier
  // results stay rather than being replaced by a run the user abandoned.
  throwIfInterrupted();
  if (!folder.commit()) {
    progress.message("note: " + summary.outputDirectory.string() +
                     " could not be swapped atomically (mount point or file system without "
                     "RENAME_EXCHANGE); its files were replaced one by one");
  }
  return summary;
}

namespace {
// Renders with the configured renderer (see RendererFactory.h).
capture::RenderResult renderVolume(const config::RunConfig& config, const capture::RenderJob& job,
                                   const RunOptions& options, capture::SegmentSink& sink,
                                   const capture::ProgressCallback& progress, RunSummary& summary) {
  const RendererChoice choice = makeRenderer(config, options.eglPlatform);
  summary.backend = choice.backend;
  summary.device = choice.renderer->description();
  return choice.renderer->render(job, sink, progress);
}

// Writes every output into `dir`, the staging folder.
void writeOutputs(const config::RunConfig& config, const capture::RenderJob& job,
                  const RunOptions& options, const std::filesystem::path& dir, Progress& progress,
                  RunSummary& summary) {
  const config::OutputConfig& out = config.output;
  // The sensors see what the render saves (the total volume, plus the direct
  // component and the depth when the output writes them), so `tofsim sense`
  // on the saved folder reproduces their outputs byte for byte.
  // They are fed each segment as it is written, so that no one holds the
  // whole volume unless the video or the frames (time-major: every pixel of
  // one bin) need it. The light by bounce order (cwtof multipath_by_order)
  // is given them whether or not the components are saved; `tofsim sense`
  // needs the files (direct.npy, bounce<k>.npy) to redo it.
  std::optional<SensorStreams> sensorStreams;
  const std::optional<int32_t> bounces = sensorBounces(config);
  if (!config.sensors.empty()) {
    const sensors::VolumeShape shape{job.camera.width, job.camera.height, capture::kChannels,
                                     job.settings.time};
    sensorStreams.emplace(config, shape, out.direct, bounces, dir);
  }
  OutputSink::Forward toSensors;
  if (sensorStreams) toSensors = [&](const sensors::PixelSpan& s) { sensorStreams->consume(s); };
  OutputSink sink(dir, out, job.camera.width, job.camera.height, job.settings.time,
                  out.frames || out.video || out.frame_pngs, toSensors, bounces.value_or(0));
  const capture::ProgressCallback onProgress = [&](std::size_t done, std::size_t total,
                                                   const std::string& what) {
    progress.update(done, total, what);
  };
  summary.result = renderVolume(config, job, options, sink, onProgress, summary);
  summary.result.nonFiniteRejected = sink.nonFiniteValues();
  progress.message("device: " + summary.device + " (backend " + summary.backend + ")");
  if (summary.result.nonFiniteRejected > 0) {
    // Shown even with -q: the outputs differ from what the renderer produced.
    std::fprintf(stderr,
                 "tofsim: warning: %zu NaN/infinite volume values written as 0 "
                 "(transient.json stats.rejected_non_finite_values)\n",
                 summary.result.nonFiniteRejected);
  }
  checkAxisAfterRender(config, job, sink, summary.result);  // throws under --strict
  if (sensorStreams) sensorStreams->checkWindows();
  sink.commit();
  if (out.transient) summary.files.push_back("transient.npy");
  if (out.direct) summary.files.push_back("direct.npy");
  if (out.indirect) summary.files.push_back("indirect.npy");
  for (const int32_t k : out.bounces)
    summary.files.push_back("bounce" + std::to_string(k) + ".npy");
  PlotRanges ranges(out.plot_ranges);
  if (out.steady) {
    const Image steady = sink.steady();
    io::writeExr(dir / "steady.exr", steady, {"R", "G", "B"});
    imaging::writeToneMappedPng(dir / "steady.png", steady, imaging::ToneMap::Global,
                                ranges.take("steady"));
    summary.files.push_back("steady.exr");
    summary.files.push_back("steady.png");
  }
  if (out.depth) {
    io::writeDepthExr(dir / "depth.exr", summary.result.depth_m);  // channels Y and Z
    io::writeNpy(dir / "depth.npy", {std::size_t(job.camera.height), std::size_t(job.camera.width)},
                 summary.result.depth_m.data.data());
    imaging::ColorScale scale;  // over the surfaces: 0 (no surface) is not a depth
    scale.nonPositiveIsNoData = true;
    scale.noDataLabel = "no surface";
    scale.range = ranges.take("depth");
    imaging::writeColormappedPng(dir / "depth.png", summary.result.depth_m, "depth [m]", scale);
    summary.files.push_back("depth.exr");
    summary.files.push_back("depth.npy");
    summary.files.push_back("depth.png");
  }
  if (out.frames) writeFrames(dir, *sink.volume(), summary.files);
  if (out.video || out.frame_pngs) writeVideo(dir, out, *sink.volume(), progress, summary.files);
  if (out.transient) {
    writeFileAtomically(
        dir / "transient.json",
        transientMetadataJson(config, job, summary.result, summary.backend, summary.device));
    summary.files.push_back("transient.json");
  }
  if (sensorStreams) {
    const Image* depth = out.depth ? &summary.result.depth_m : nullptr;
    for (std::string& f : sensorStreams->finish(depth, progress)) {
      summary.files.push_back(std::move(f));
    }
  }
  std::vector<std::string> untaken = ranges.untaken("");
  if (sensorStreams) {  // SensorStreams::finish reported the sensors' keys
    std::erase_if(untaken, [](const std::string& k) { return k.rfind("sensors/", 0) == 0; });
  }
  warnUntakenPlotRanges(untaken);
  // What was used: a glTF camera's position, view and field of view, not the
  // config's defaults, so the file reproduces the run without the glTF camera too.
  config::RunConfig used = config;
  used.camera.camera = job.camera;
  writeFileAtomically(dir / "config.effective.yaml", config::effectiveConfigYaml(used));
  summary.files.push_back("config.effective.yaml");
  if (options.batchManifest) {
    // Last: it lists the files above with their checksums, so it exists
    // only once all of them do.
    writeManifest(dir, options.batchManifest->runName, summary.files,
                  options.batchManifest->inputs);
    summary.files.push_back(kManifestName);
  }
}
}  // namespace

}  // namespace tofsim::pipeline
