#include "tofsim/pipeline/RenderRun.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>

#include "KeptAcrossRenders.h"
#include "NlosRun.h"
#include "OutputStreams.h"
#include "ProductWriters.h"
#include "RunRecord.h"
#include "SensorPasses.h"
#include "SequenceFrame.h"
#include "SequenceRun.h"
#include "StagedOutput.h"
#include "tofsim/imaging/Video.h"
#include "tofsim/pipeline/OutputEstimate.h"
#include "tofsim/pipeline/OutputProducts.h"
#include "tofsim/pipeline/PlotRanges.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/RenderCapture.h"
#include "tofsim/scene/GltfLoader.h"
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

// Writes every output into `dir`, the staging folder: streamed while the
// render runs (OutputStreams), written from what it gave after it
// (writeProduct), the sensors' files, then the record.
void writeOutputs(const config::RunConfig& config, const capture::RenderJob& job,
                  const RunOptions& options, const std::filesystem::path& dir, Progress& progress,
                  RunSummary& summary, PreparedRenderer* prepared, const SequenceFrame* frame) {
  const std::vector<OutputProduct> products = renderProducts(config);
  // Its encoder loaded before the render, not found missing after it.
  if (config.output.video || (config.sequence && config.sequence->video)) {
    imaging::requireVideoEncoder();
  }
  OutputStreams streams(config, job, dir, products, options.psfOnTransient, progress);
  SensorStreams* sensors = streams.sensors();
  if (frame && sensors) {
    renderSensorPasses(config, *frame, *sensors, streams.consumers(), streams.bounces(), progress);
  }
  RenderedCapture rendered =
      renderCapture(config, job, frame ? *frame->renderer : prepared->renderer(config),
                    streams.consumers(), progress);
  if (!frame) progress.message("device: " + rendered.device + " (backend " + rendered.backend + ")");
  summary.backend = rendered.backend;
  summary.device = rendered.device;
  summary.result = std::move(rendered.result);
  streams.renderDone();
  PlotRanges ranges(config.output.plot_ranges);
  for (const OutputProduct& p : products) {
    writeProduct(p, config, job, dir, rendered.steady, summary, streams, ranges, progress);
    summary.files.insert(summary.files.end(), p.files.begin(), p.files.end());
  }
  CaptureFile* capture = streams.capture();
  if (sensors) {
    const Image* depth = config.output.depth ? &summary.result.depth_m : nullptr;
    const std::vector<std::string> sensorFiles = sensors->finish(depth, progress);
    if (capture) capture->addSensorFiles(dir, sensorFiles);
    summary.files.insert(summary.files.end(), sensorFiles.begin(), sensorFiles.end());
  }
  if (capture) capture->commit();
  std::vector<std::string> untaken = ranges.untaken("");
  if (sensors) {  // SensorStreams::finish reported the sensors' keys
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
