#include "tofsim/pipeline/RenderRun.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>

#include "BinMajorSpill.h"
#include "CaptureFile.h"
#include "KeptAcrossRenders.h"
#include "NlosRun.h"
#include "SequenceFrame.h"
#include "SequenceRun.h"
#include "SequenceVideo.h"
#include "StagedOutput.h"
#include "tofsim/capture/VolumeCollector.h"  // defaultChannelNames
#include "tofsim/imaging/Pictures.h"
#include "tofsim/imaging/Video.h"
#include "tofsim/io/DepthExr.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/Manifest.h"
#include "tofsim/pipeline/Metadata.h"
#include "tofsim/pipeline/OutputEstimate.h"
#include "tofsim/pipeline/OutputProducts.h"
#include "tofsim/pipeline/PixelSpanSink.h"
#include "tofsim/pipeline/PlotRanges.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/RenderCapture.h"
#include "tofsim/pipeline/SensorStreams.h"
#include "tofsim/pipeline/VolumeFileSink.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

void reportLoad(const scene::LoadReport& report, const Progress& progress, bool animationsPlayed) {
  for (const std::string& w : report.warnings) progress.message("scene: " + w);
  if (report.skippedPrimitives > 0) {
    progress.message("scene: skipped " + std::to_string(report.skippedPrimitives) +
                     " point/line primitives");
  }
  if (report.emissiveMaterials + report.transmissiveMaterials > 0) {
    progress.message("scene: emissive/transmissive materials render as diffuse base colour");
  }
  if (report.animations > 0 && !animationsPlayed) {
    progress.message("scene: " + std::to_string(report.animations) +
                     " animation(s) not played: rendered at the rest pose (the nodes' own "
                     "transforms; tofsim info lists them; `sequence:` plays them)");
  }
}

namespace {

void writeFrames(const std::filesystem::path& directory, const imaging::BinFrames& frames) {
  std::filesystem::create_directories(directory / "frames");
  std::vector<std::string> channels = capture::defaultChannelNames(frames.channels);
  for (int32_t t = 0; t < frames.axis.bins; ++t) {
    throwIfInterrupted();
    Image frame(frames.width, frames.height, frames.channels);
    frames.readBin(t, frame.data.data());
    io::writeExr(directory / files::frameExr(t), frame, channels);
  }
}

// transient.mp4 and/or frames/frame_NNNNN.png (the same pictures).
void writeVideo(const std::filesystem::path& dir, const config::OutputConfig& out,
                const imaging::BinFrames& frames, const Progress& progress) {
  const imaging::VideoOptions options = videoOptions(out);
  progress.message(
      "video: " + std::to_string(imaging::videoFrameCount(frames.axis.bins, out.video_stride)) +
      " frame(s)");
  imaging::writeTransientVideo(out.video ? dir / files::kVideo : std::filesystem::path(), frames,
                               options, out.frame_pngs ? dir / "frames" : std::filesystem::path());
}

// The video's and the frames' bin-major copy of the volume, in the staging
// folder (on the outputs' disk, not a RAM-backed /tmp); gone before the
// folder is committed.
constexpr const char* kBinMajorSpillName = ".transient_bin_major.tmp";

}  // namespace

namespace {
// `prepared` gives the renderer of a run; a sequence's frame brings its own.
void writeOutputs(const config::RunConfig& config, const capture::RenderJob& job,
                  const RunOptions& options, const std::filesystem::path& dir, Progress& progress,
                  RunSummary& summary, PreparedRenderer* prepared, const SequenceFrame* frame);
RunSummary renderScene(const config::RunConfig& config, const scene::Scene& scene,
                       const RunOptions& options, Progress& progress, PreparedRenderer* prepared,
                       const SequenceFrame* frame = nullptr);

}  // namespace

RunSummary runRender(const config::RunConfig& config, const RunOptions& options) {
  PreparedRenderer prepared(options.eglPlatform);
  return runRender(config, prepared, options);
}

RunSummary runRender(const config::RunConfig& config, PreparedRenderer& prepared,
                     const RunOptions& options) {
  if (config.nlos) return runNlosRender(config, options);
  if (config.sequence) return runSequenceRender(config, options);
  Progress progress("render", options.quiet);  // its time includes the scene's loading
  prepared.prepare(config);
  reportLoad(prepared.loadReport(), progress, false);
  return renderScene(config, prepared.scene(), options, progress, &prepared);
}

RunSummary renderSequenceFrame(const config::RunConfig& config, const scene::Scene& scene,
                               const RunOptions& options, Progress& progress,
                               const SequenceFrame& frame) {
  return renderScene(config, scene, options, progress, nullptr, &frame);
}

RunSummary runRender(const config::RunConfig& config, const scene::Scene& scene,
                     const RunOptions& options) {
  TOFSIM_CHECK(!config.nlos);
  Progress progress("render", options.quiet);
  PreparedRenderer prepared(options.eglPlatform);
  return renderScene(config, scene, options, progress, &prepared);
}

std::string renderSummaryText(const config::RunConfig& config, const RunSummary& summary) {
  char line[512];
  std::snprintf(line, sizeof line, "render: %.2f s, %zu segment(s); wrote %zu file(s) to %s\n",
                summary.result.seconds, summary.result.segments, summary.files.size(),
                summary.outputDirectory.string().c_str());
  std::string text = line;
  const capture::RenderSettings& s = config.render;
  if (config.renderer != config::RendererKind::Reference && s.adaptive_pixel_samples &&
      s.pixel_samples > 1) {
    const double pixels =
        static_cast<double>(config.camera.camera.width) * config.camera.camera.height;
    std::snprintf(line, sizeof line, "render: %zu pixel(s) (%.1f %%) at edges took %d x %d samples\n",
                  summary.result.sampledPixels,
                  100.0 * static_cast<double>(summary.result.sampledPixels) / pixels,
                  s.pixel_samples, s.pixel_samples);
    text += line;
  }
  return text;
}

namespace {
RunSummary renderScene(const config::RunConfig& config, const scene::Scene& scene,
                       const RunOptions& options, Progress& progress, PreparedRenderer* prepared,
                       const SequenceFrame* frame) {
  const capture::RenderJob job =
      frame ? frame->jobAt(0.0) : prepareCapture(config, scene);  // fails under --strict

  RunSummary summary;
  summary.outputDirectory =
      options.outputDirectory.empty() ? config.output.directory : options.outputDirectory;
  // Checked and locked before any rendering, so that a bad -o or a second
  // writer fails in a second. Everything is written into a staging folder
  // that replaces the earlier results only when complete: an error, Ctrl-C or
  // kill -9 before that leaves the earlier set untouched.
  StagedFolder folder(summary.outputDirectory, keptAcrossRenders);
  noteLinkedOutput(folder, progress);
  checkOutputsFit(estimateOutputs(config), config, folder.staging());
  writeOutputs(config, job, options, folder.staging(), progress, summary, prepared, frame);
  // A signal that came during the last step still means "stop": the earlier
  // results stay rather than being replaced by a run the user abandoned.
  throwIfInterrupted();
  commitOutput(folder, progress);
  return summary;
}

void writeSteady(const std::filesystem::path& dir, const Image& steady, PlotRanges& ranges) {
  io::writeExr(dir / files::kSteadyExr, steady, {"R", "G", "B"});
  imaging::writeToneMappedPng(dir / files::kSteadyPng, steady, imaging::ToneMap::Global,
                              ranges.take("steady"));
}

void writeDepth(const std::filesystem::path& dir, const Image& depth_m, PlotRanges& ranges) {
  io::writeDepthExr(dir / files::kDepthExr, depth_m);  // channels Y and Z
  io::writeNpy(dir / files::kDepthNpy, {std::size_t(depth_m.height), std::size_t(depth_m.width)},
               depth_m.data.data());
  imaging::ColorScale scale;  // over the surfaces: 0 (no surface) is not a depth
  scale.nonPositiveIsNoData = true;
  scale.noDataLabel = "no surface";
  scale.range = ranges.take("depth");
  imaging::writeColormappedPng(dir / files::kDepthPng, depth_m, "depth [m]", scale);
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

// The bounce components the consumers read: bounce<k>.npy's and the sensors'
// bounces 1..N (N = 1 reads the indirect light).
std::vector<int32_t> bouncesRead(const config::OutputConfig& out, int32_t sensorBounces) {
  std::vector<int32_t> bounces = out.bounces;
  for (int32_t k = 1; sensorBounces >= 2 && k <= sensorBounces; ++k) {
    if (std::find(bounces.begin(), bounces.end(), k) == bounces.end()) bounces.push_back(k);
  }
  return bounces;
}

// Writes product `p` from what the render gave (its Writer::Volume files
// were streamed while it ran).
void writeProduct(const OutputProduct& p, const config::RunConfig& config,
                  const capture::RenderJob& job, const std::filesystem::path& dir,
                  const Image& steady, const RunSummary& summary,
                  const std::function<const imaging::BinFrames&()>& binFrames, PlotRanges& ranges,
                  const Progress& progress, CaptureFile* capture) {
  switch (p.writer) {
    case Writer::Volume:
    case Writer::Capture:  // committed after the sensors (writeOutputs)
      break;
    case Writer::Steady:
      writeSteady(dir, steady, ranges);
      if (capture) capture->addSteady(steady);
      break;
    case Writer::Depth:
      writeDepth(dir, summary.result.depth_m, ranges);
      if (capture) capture->addDepth(summary.result.depth_m);
      break;
    case Writer::Frames:
      writeFrames(dir, binFrames());
      break;
    case Writer::Video:
      writeVideo(dir, config.output, binFrames(), progress);
      break;
    case Writer::Metadata: {
      const std::string json =
          transientMetadataJson(config, job, summary.result, summary.backend, summary.device);
      writeFileAtomically(dir / files::kMetadata, json);
      if (capture) capture->describeVolumes(json);
      break;
    }
  }
}

// A moving scene's frame: the light at the times within the frame at which
// some sensor samples it (CW-ToF's raws), other than the frame's own, each
// a render of its own given the sensors alone; then the scene back at the
// frame's time for the reference pass (moved, and so prepared again, only
// when it was moved away).
void renderSensorPasses(const config::RunConfig& config, const SequenceFrame& frame,
                        SensorStreams& sensors, const CaptureConsumers& like,
                        std::optional<int32_t> bounces, Progress& progress) {
  const std::vector<double> offsets = sensors.passOffsets_s();
  PixelSpanSink spans([&](const sensors::PixelSpan& s) { sensors.consume(s); },
                      bounces.value_or(0));
  CaptureConsumers consumers;
  consumers.sinks = {&spans};
  consumers.bounces = like.bounces;
  consumers.psfOnRaws = like.psfOnRaws;
  for (std::size_t i = 1; i < offsets.size(); ++i) {
    throwIfInterrupted();
    progress.message("sensor pass " + std::to_string(i) + "/" + std::to_string(offsets.size() - 1) +
                     " at +" + std::to_string(offsets[i] * 1e3) + " ms");
    const capture::RenderJob job = frame.jobAt(offsets[i]);
    sensors.beginPass(offsets[i]);
    renderCapture(config, job, *frame.renderer, consumers, progress);
  }
  if (offsets.size() > 1) frame.jobAt(0.0);
  sensors.beginPass(0.0);
}

// Writes every output into `dir`, the staging folder.
void writeOutputs(const config::RunConfig& config, const capture::RenderJob& job,
                  const RunOptions& options, const std::filesystem::path& dir, Progress& progress,
                  RunSummary& summary, PreparedRenderer* prepared, const SequenceFrame* frame) {
  const config::OutputConfig& out = config.output;
  const std::vector<OutputProduct> products = renderProducts(config);
  // Its encoder loaded before the render, not found missing after it.
  if (config.output.video || (config.sequence && config.sequence->video)) {
    imaging::requireVideoEncoder();
  }
  // The sensors see what the render saves (the total volume, plus the direct
  // component and the depth when the output writes them), so `tofsim sense`
  // on the saved folder reproduces their outputs byte for byte.
  // They are fed each segment as it is written, so that no one holds the
  // whole volume. The video and the frames (time-major: every pixel of one
  // bin) get it through a bin-major temporary file. The light by bounce order
  // (cwtof multipath_by_order) is given the sensors whether or not the
  // components are saved; `tofsim sense` needs the files (direct.npy,
  // bounce<k>.npy) to redo it.
  const capture::Camera& camera = job.camera();
  const sensors::VolumeShape shape{camera.width, camera.height, capture::kChannels,
                                   job.settings.time};
  const std::optional<int32_t> bounces = sensorBounces(config);
  // The lens's PSF on every bin, or on the CW-ToF raws and the steady image
  // when nothing written needs the blurred transient (PsfPath.h).
  const PsfPath psf = choosePsfPath(config, options.psfOnTransient);
  if (psf == PsfPath::Raws) {
    progress.message(
        "camera.psf: on the CW-ToF raws and the steady image (no output needs the blurred "
        "transient)");
  }
  std::optional<SensorStreams> sensorStreams;
  if (!config.sensors.empty())
    sensorStreams.emplace(config, shape, out.direct, bounces, dir, &camera, psf);
  std::optional<BinMajorSpill> spill;
  if (out.frames || out.video || out.frame_pngs) spill.emplace(dir / kBinMajorSpillName, shape);
  // output.format: hdf5: the volumes and the other arrays in one file.
  std::optional<CaptureFile> capture;
  if (out.format == config::OutputFormat::Hdf5) {
    capture.emplace(dir / files::kCapture, config.cpu_threads);
  }
  std::vector<std::unique_ptr<VolumeFileSink>> volumeFiles;
  CaptureConsumers consumers;
  for (const OutputProduct& p : products) {
    if (p.writer != Writer::Volume) continue;
    if (capture) {
      consumers.sinks.push_back(&capture->volume(p.dataset, p.component, camera.width,
                                                 camera.height, job.settings.time.bins));
      continue;
    }
    volumeFiles.push_back(std::make_unique<VolumeFileSink>(
        dir / p.files.at(0), p.component, camera.width, camera.height, job.settings.time));
    consumers.sinks.push_back(volumeFiles.back().get());
  }
  std::optional<PixelSpanSink> spans;
  if (sensorStreams || spill) {
    spans.emplace(
        [&](const sensors::PixelSpan& s) {
          if (sensorStreams) sensorStreams->consume(s);
          if (spill) spill->append(s);
        },
        bounces.value_or(0));
    consumers.sinks.push_back(&*spans);
  }
  // The light before the PSF, for the CW-ToF sensors' cwtof_psf_error.
  std::optional<PixelSpanSink> sharpSpans;
  if (sensorStreams && psf == PsfPath::Transient) {
    sharpSpans.emplace([&](const sensors::PixelSpan& s) { sensorStreams->consumeBeforePsf(s); }, 0);
    consumers.beforePsf.push_back(&*sharpSpans);
  }
  consumers.psfOnRaws = psf == PsfPath::Raws;
  consumers.bounces = bouncesRead(out, bounces.value_or(0));
  if (frame && sensorStreams) {
    renderSensorPasses(config, *frame, *sensorStreams, consumers, bounces, progress);
  }
  RenderedCapture rendered = renderCapture(
      config, job, frame ? *frame->renderer : prepared->renderer(config), consumers, progress);
  if (!frame) progress.message("device: " + rendered.device + " (backend " + rendered.backend + ")");
  summary.backend = rendered.backend;
  summary.device = rendered.device;
  summary.result = std::move(rendered.result);
  if (sensorStreams) sensorStreams->checkWindows();
  for (const std::unique_ptr<VolumeFileSink>& file : volumeFiles) file->commit();
  PlotRanges ranges(out.plot_ranges);
  std::optional<imaging::BinFrames> frames;  // from the spill, when a writer first needs them
  const std::function<const imaging::BinFrames&()> binFrames = [&]() -> const imaging::BinFrames& {
    if (!frames) frames.emplace(spill->frames());
    return *frames;
  };
  for (const OutputProduct& p : products) {
    writeProduct(p, config, job, dir, rendered.steady, summary, binFrames, ranges, progress,
                 capture ? &*capture : nullptr);
    summary.files.insert(summary.files.end(), p.files.begin(), p.files.end());
  }
  if (sensorStreams) {
    const Image* depth = out.depth ? &summary.result.depth_m : nullptr;
    const std::vector<std::string> sensorFiles = sensorStreams->finish(depth, progress);
    if (capture) capture->addSensorFiles(dir, sensorFiles);
    summary.files.insert(summary.files.end(), sensorFiles.begin(), sensorFiles.end());
  }
  if (capture) capture->commit();
  std::vector<std::string> untaken = ranges.untaken("");
  if (sensorStreams) {  // SensorStreams::finish reported the sensors' keys
    std::erase_if(untaken, [](const std::string& k) { return k.rfind("sensors/", 0) == 0; });
  }
  warnUntakenPlotRanges(untaken);
  if (frame) {
    frame->record(dir, summary.files, summary.result);
  } else {
    writeRecord(config, job, options, dir, summary.files);
  }
}
}  // namespace

}  // namespace tofsim::pipeline
