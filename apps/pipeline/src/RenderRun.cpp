#include "tofsim/pipeline/RenderRun.h"

#include <cstdio>
#include <optional>

#include "BinMajorSpill.h"
#include "KeptAcrossRenders.h"
#include "NlosRun.h"
#include "tofsim/capture/VolumeCollector.h"
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

void writeFrames(const std::filesystem::path& directory, const imaging::BinFrames& frames,
                 std::vector<std::string>& files) {
  std::filesystem::create_directories(directory / "frames");
  std::vector<std::string> channels = capture::defaultChannelNames(frames.channels);
  for (int32_t t = 0; t < frames.axis.bins; ++t) {
    throwIfInterrupted();
    Image frame(frames.width, frames.height, frames.channels);
    frames.readBin(t, frame.data.data());
    char name[64];
    std::snprintf(name, sizeof name, "frames/frame_%05d.exr", t);
    io::writeExr(directory / name, frame, channels);
    files.push_back(name);
  }
}

// transient.mp4 and/or frames/frame_NNNNN.png (the same pictures).
void writeVideo(const std::filesystem::path& dir, const config::OutputConfig& out,
                const imaging::BinFrames& frames, const Progress& progress,
                std::vector<std::string>& files) {
  imaging::VideoOptions options;
  options.toneMap = out.video_tone_map == config::VideoToneMap::Log ? imaging::ToneMap::Log
                                                                    : imaging::ToneMap::Global;
  options.stride = out.video_stride;
  options.window = out.video_window;
  options.fps = out.video_fps;
  progress.message(
      "video: " + std::to_string(imaging::videoFrameCount(frames.axis.bins, out.video_stride)) +
      " frame(s)");
  imaging::writeTransientVideo(out.video ? dir / "transient.mp4" : std::filesystem::path(), frames,
                               options, out.frame_pngs ? dir / "frames" : std::filesystem::path());
  if (out.video) files.push_back("transient.mp4");
  if (out.frame_pngs) {
    for (int32_t t = 0; t < frames.axis.bins; t += out.video_stride) {
      char name[64];
      std::snprintf(name, sizeof name, "frames/frame_%05d.png", t);
      files.push_back(name);
    }
  }
}

// The video's and the frames' bin-major copy of the volume, in the staging
// folder (on the outputs' disk, not a RAM-backed /tmp); gone before the
// folder is committed.
constexpr const char* kBinMajorSpillName = ".transient_bin_major.tmp";

}  // namespace

namespace {
void writeOutputs(const config::RunConfig& config, const capture::RenderJob& job,
                  const RunOptions& options, const std::filesystem::path& dir, Progress& progress,
                  RunSummary& summary);

}  // namespace

RunSummary runRender(const config::RunConfig& config, const RunOptions& options) {
  if (config.nlos) return runNlosRender(config, options);
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
  StagedFolder folder(summary.outputDirectory, keptAcrossRenders);
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
void writeSteady(const std::filesystem::path& dir, const Image& steady, PlotRanges& ranges,
                 std::vector<std::string>& files) {
  io::writeExr(dir / "steady.exr", steady, {"R", "G", "B"});
  imaging::writeToneMappedPng(dir / "steady.png", steady, imaging::ToneMap::Global,
                              ranges.take("steady"));
  files.push_back("steady.exr");
  files.push_back("steady.png");
}

void writeDepth(const std::filesystem::path& dir, const Image& depth_m, PlotRanges& ranges,
                std::vector<std::string>& files) {
  io::writeDepthExr(dir / "depth.exr", depth_m);  // channels Y and Z
  io::writeNpy(dir / "depth.npy", {std::size_t(depth_m.height), std::size_t(depth_m.width)},
               depth_m.data.data());
  imaging::ColorScale scale;  // over the surfaces: 0 (no surface) is not a depth
  scale.nonPositiveIsNoData = true;
  scale.noDataLabel = "no surface";
  scale.range = ranges.take("depth");
  imaging::writeColormappedPng(dir / "depth.png", depth_m, "depth [m]", scale);
  files.push_back("depth.exr");
  files.push_back("depth.npy");
  files.push_back("depth.png");
}

// The run's record: the effective config and, for a batch, the manifest.
void writeRecord(const config::RunConfig& config, const capture::RenderJob& job,
                 const RunOptions& options, const std::filesystem::path& dir,
                 std::vector<std::string>& files) {
  // What was used: a glTF camera's position, view and field of view, not the
  // config's defaults, so the file reproduces the run without the glTF camera too.
  config::RunConfig used = config;
  used.camera.camera = job.camera();
  writeFileAtomically(dir / "config.effective.yaml", config::effectiveConfigYaml(used));
  files.push_back("config.effective.yaml");
  if (options.batchManifest) {
    // Last: it lists the files above with their checksums, so it exists
    // only once all of them do.
    writeManifest(dir, options.batchManifest->runName, files, options.batchManifest->inputs);
    files.push_back(kManifestName);
  }
}

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
  // whole volume. The video and the frames (time-major: every pixel of one
  // bin) get it through a bin-major temporary file. The light by bounce order
  // (cwtof multipath_by_order) is given the sensors whether or not the
  // components are saved; `tofsim sense` needs the files (direct.npy,
  // bounce<k>.npy) to redo it.
  const sensors::VolumeShape shape{job.camera().width, job.camera().height, capture::kChannels,
                                   job.settings.time};
  const std::optional<int32_t> bounces = sensorBounces(config);
  std::optional<SensorStreams> sensorStreams;
  if (!config.sensors.empty()) sensorStreams.emplace(config, shape, out.direct, bounces, dir);
  std::optional<BinMajorSpill> spill;
  if (out.frames || out.video || out.frame_pngs) spill.emplace(dir / kBinMajorSpillName, shape);
  OutputSink::Forward forward;
  if (sensorStreams || spill) {
    forward = [&](const sensors::PixelSpan& s) {
      if (sensorStreams) sensorStreams->consume(s);
      if (spill) spill->append(s);
    };
  }
  OutputSink sink(dir, out, job.camera().width, job.camera().height, job.settings.time, forward,
                  bounces.value_or(0));
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
  if (out.steady) writeSteady(dir, sink.steady(), ranges, summary.files);
  if (out.depth) writeDepth(dir, summary.result.depth_m, ranges, summary.files);
  if (spill) {
    const imaging::BinFrames frames = spill->frames();
    if (out.frames) writeFrames(dir, frames, summary.files);
    if (out.video || out.frame_pngs) writeVideo(dir, out, frames, progress, summary.files);
  }
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
  writeRecord(config, job, options, dir, summary.files);
}
}  // namespace

}  // namespace tofsim::pipeline
