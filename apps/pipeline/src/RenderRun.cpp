#include "tofsim/pipeline/RenderRun.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>

#include "LidarRun.h"
#include "NlosRun.h"
#include "OutputStreams.h"
#include "ProductWriters.h"
#include "RunFolder.h"
#include "RunRecord.h"
#include "SensorPasses.h"
#include "SequenceFrame.h"
#include "SequenceRun.h"
#include "tofsim/imaging/Video.h"
#include "tofsim/pipeline/CaptureLoop.h"
#include "tofsim/pipeline/Metadata.h"
#include "tofsim/pipeline/OutputEstimate.h"
#include "tofsim/pipeline/OutputProducts.h"
#include "tofsim/pipeline/PlotRanges.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/RenderCapture.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"

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
RunSummary renderScene(const config::RunConfig& config, const scene::Scene& scene,
                       const RunOptions& options, Progress& progress, PreparedRenderer& prepared);
}  // namespace

RunSummary runRender(const config::RunConfig& config, const RunOptions& options) {
  PreparedRenderer prepared(options.eglPlatform);
  return runRender(config, prepared, options);
}

RunSummary runRender(const config::RunConfig& config, PreparedRenderer& prepared,
                     const RunOptions& options) {
  if (config.nlos) return runNlosRender(config, prepared, options);
  if (config.lidar) return runLidarRender(config, prepared, options);
  if (config.sequence) return runSequenceRender(config, prepared, options);
  Progress progress("render", options.quiet);  // its time includes the scene's loading
  prepared.prepare(config);
  reportLoad(prepared.loadReport(), progress, false);
  return renderScene(config, prepared.scene(), options, progress, prepared);
}

RunSummary runRender(const config::RunConfig& config, const scene::Scene& scene,
                     const RunOptions& options) {
  TOFSIM_CHECK(!config.nlos && !config.lidar);
  Progress progress("render", options.quiet);
  PreparedRenderer prepared(options.eglPlatform);
  return renderScene(config, scene, options, progress, prepared);
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

// A render's outputs as a capture's sink (CaptureLoop.h). Before the render:
// the output folder checked and locked (a bad -o or a second writer fails
// in a second), the streams opened, and a frame's sensor passes rendered.
// Everything is written into a staging folder that replaces the earlier
// results only when complete: an error, Ctrl-C or kill -9 before that (an
// unfinished sink) leaves the earlier set untouched.
class OutputSink : public CaptureSink {
 public:
  OutputSink(const config::RunConfig& config, const capture::RenderJob& job,
             const RunOptions& options, Progress& progress, RunSummary& summary,
             const SequenceFrame* frame)
      : config_(config),
        job_(job),
        options_(options),
        progress_(progress),
        summary_(summary),
        frame_(frame) {
    OutputEstimate outputs = estimateOutputs(config);
    if (!options.sharedVolume.empty()) outputs.temporaryBytes += volumeBytes(config);
    folder_.emplace(config, options, outputs, progress);
    summary.outputDirectory = folder_->path();
    products_ = renderProducts(config);
    // Its encoder loaded before the render, not found missing after it.
    if (config.output.video || (config.sequence && config.sequence->video)) {
      imaging::requireVideoEncoder();
    }
    streams_.emplace(config, job, folder_->staging(), products_, options.psfOnTransient,
                     options.sharedVolume, progress);
    SensorStreams* sensors = streams_->sensors();
    if (frame && sensors) {
      renderSensorPasses(config, *frame, *sensors, streams_->consumers(), streams_->bounces(),
                         progress);
    }
    chain_.emplace(config, job, streams_->consumers());
  }
  capture::SegmentSink& segments() override { return chain_->first(); }
  void finish(const capture::RenderResult& result, const RendererChoice& renderer) override {
    RenderedCapture rendered = chain_->finish(result, renderer);
    if (!frame_) {
      progress_.message("device: " + rendered.device + " (backend " + rendered.backend + ")");
    }
    summary_.backend = rendered.backend;
    summary_.device = rendered.device;
    summary_.result = std::move(rendered.result);
    writeOutputs(rendered.steady);
    // The streams' scratch files (the bin-major spill) go before the
    // staging folder becomes the set.
    chain_.reset();
    streams_.reset();
    // A signal that came during the last step still means "stop": the
    // earlier results stay rather than being replaced by a run the user
    // abandoned.
    folder_->commit();
  }

 private:
  void writeOutputs(const Image& steady);

  const config::RunConfig& config_;
  const capture::RenderJob& job_;
  const RunOptions& options_;
  Progress& progress_;
  RunSummary& summary_;
  const SequenceFrame* frame_;
  std::optional<RunFolder> folder_;
  std::vector<OutputProduct> products_;
  std::optional<OutputStreams> streams_;
  std::optional<CaptureChain> chain_;
};

// After the render, into the staging folder: the products written from what
// it gave (writeProduct), the sensors' files, then the record.
void OutputSink::writeOutputs(const Image& steady) {
  const std::filesystem::path& dir = folder_->staging();
  OutputStreams& streams = *streams_;
  SensorStreams* sensors = streams.sensors();
  streams.renderDone();
  PlotRanges ranges(config_.output.plot_ranges);
  for (const OutputProduct& p : products_) {
    writeProduct(p, config_, job_, dir, steady, summary_, streams, ranges, progress_);
    summary_.files.insert(summary_.files.end(), p.files.begin(), p.files.end());
  }
  if (!options_.sharedVolume.empty()) {  // its axis, for the runs that take it
    writeFileAtomically(options_.sharedVolume / files::kMetadata,
                        transientMetadataJson(config_, job_, summary_.result, summary_.backend,
                                              summary_.device));
  }
  CaptureFile* capture = streams.capture();
  if (sensors) {
    const Image* depth = config_.output.depth ? &summary_.result.depth_m : nullptr;
    const std::vector<std::string> sensorFiles = sensors->finish(depth, progress_);
    if (capture) capture->addSensorFiles(dir, sensorFiles);
    summary_.files.insert(summary_.files.end(), sensorFiles.begin(), sensorFiles.end());
  }
  if (capture) capture->commit();
  std::vector<std::string> untaken = ranges.untaken("");
  if (sensors) {  // SensorStreams::finish reported the sensors' keys
    std::erase_if(untaken, [](const std::string& k) { return k.rfind("sensors/", 0) == 0; });
  }
  warnUntakenPlotRanges(untaken);
  if (frame_) {
    frame_->record(dir, summary_.files, summary_.result);
  } else {
    writeRecord(config_, job_, options_, dir, summary_.files);
  }
}

// One capture through the loop: the job (fails under --strict before the
// output folder is touched), then its outputs.
RunSummary renderScene(const config::RunConfig& config, const scene::Scene& scene,
                       const RunOptions& options, Progress& progress, PreparedRenderer& prepared) {
  RunSummary summary;
  CaptureLoopOptions loop;
  loop.withinCapture = [&](std::size_t done, std::size_t total, const std::string& what) {
    progress.update(done, total, what);
  };
  renderCaptures(
      prepared, config, 1, [&](std::size_t) { return prepareCapture(config, scene); },
      [&](std::size_t, const capture::RenderJob& job) {
        return outputSink(config, job, options, progress, summary, nullptr);
      },
      loop);
  return summary;
}

}  // namespace

std::unique_ptr<CaptureSink> outputSink(const config::RunConfig& config,
                                        const capture::RenderJob& job, const RunOptions& options,
                                        Progress& progress, RunSummary& summary,
                                        const SequenceFrame* frame) {
  return std::make_unique<OutputSink>(config, job, options, progress, summary, frame);
}

}  // namespace tofsim::pipeline
