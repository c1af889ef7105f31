#include "tofsim/pipeline/NlosRender.h"

#include <chrono>
#include <memory>

#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/pipeline/CaptureLoop.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/util/ParallelFor.h"
#include "tofsim/util/Random.h"

namespace tofsim::pipeline {

namespace {

// Fewer points per capture than this: parallel over captures instead.
constexpr std::size_t kPointsForParallelGather = 256;

// Capture c's light, kept in c's own columns of H[t, point] = R + G + B of
// the indirect light (tal render's sum): the captures write disjoint parts.
class NlosCaptureSink : public CaptureSink {
 public:
  NlosCaptureSink(NlosVolume& out, std::size_t capture, std::size_t perCapture,
                  const TimeAxis& axis)
      : out_(out),
        capture_(capture),
        perCapture_(perCapture),
        collector_(static_cast<int32_t>(perCapture), 1, axis, capture::kChannels) {}
  capture::SegmentSink& segments() override { return collector_; }
  void finish(const capture::RenderResult&, const RendererChoice&) override {
    const std::size_t bins = static_cast<std::size_t>(out_.axis.bins);
    const std::size_t points = out_.H.size() / bins;
    const float* v = collector_.indirect.data();
    for (std::size_t k = 0; k < perCapture_; ++k) {
      const std::size_t point = capture_ * perCapture_ + k;
      for (std::size_t t = 0; t < bins; ++t) {
        const float* rgb = v + (k * bins + t) * capture::kChannels;
        out_.H[t * points + point] = rgb[0] + rgb[1] + rgb[2];
      }
    }
  }

 private:
  NlosVolume& out_;
  std::size_t capture_, perCapture_;
  capture::VolumeCollector collector_;
};

}  // namespace

uint64_t nlosCaptureSeed(uint64_t seed, std::size_t capture) {
  // Pcg32::forUnit's mix of (seed, index), one level up: capture c's pixels
  // draw from forUnit(nlosCaptureSeed(seed, c), pixel).
  uint64_t index = capture;
  uint64_t mix = seed ^ splitMix64(index);
  return splitMix64(mix);
}

NlosVolume renderNlosScan(const config::RunConfig& config, const scene::Scene& scene,
                          const NlosScanGeometry& scan, const capture::ProgressCallback& progress,
                          gl::EglPlatform eglPlatform) {
  PreparedRenderer prepared(eglPlatform);
  return renderNlosScan(config, scene, scan, prepared, progress);
}

NlosVolume renderNlosScan(const config::RunConfig& config, const scene::Scene& scene,
                          const NlosScanGeometry& scan, PreparedRenderer& prepared,
                          const capture::ProgressCallback& progress) {
  const auto start = std::chrono::steady_clock::now();
  NlosVolume out;
  out.axis = config.render.time;
  out.captures = scan.captureCount();
  const std::size_t perCapture = scan.pointsPerCapture();
  const auto bins = static_cast<std::size_t>(out.axis.bins);
  out.shape = {bins};
  for (std::size_t n : scan.pointShape()) out.shape.push_back(n);
  out.H.assign(bins * out.captures * perCapture, 0.0f);

  const bool reference = config.renderer == config::RendererKind::Reference;
  const int threads = resolveThreads(reference ? config.reference.threads : config.cpu_threads);
  // One GL context, current on this thread: its captures one after another.
  const bool gl = !reference && prepared.specFor(config).backend == config::IrBackendKind::Gl;
  const bool overCaptures = !gl && perCapture < kPointsForParallelGather && out.captures > 1;
  const int backendThreads = overCaptures ? 1 : threads;
  // Parallel over captures: single-threaded renderers, one per worker.
  config::RunConfig rendererConfig = config;
  if (overCaptures) rendererConfig.cpu_threads = rendererConfig.reference.threads = 1;

  CaptureLoopOptions loop;
  loop.workers = overCaptures ? threads : 1;
  loop.captureDone = progress;
  loop.unit = "laser positions";
  const CaptureLoopStats stats = renderCaptures(
      prepared, rendererConfig, out.captures,
      [&](std::size_t c) {
        const NlosCapture spec = scan.capture(c, config, scene);
        capture::RenderJob job;
        job.scene = &scene;
        job.imager = spec.points;
        job.light = spec.laser;
        job.settings = config.render;
        job.settings.time.start_s += spec.axisShift_s;
        job.settings.indirect.trace_threads = backendThreads;
        // Points are points: no sub-pixel samples (their steps are zero).
        job.settings.pixel_samples = 1;
        job.settings.adaptive_pixel_samples = false;
        // The reference's paths: their own per laser position (see nlosCaptureSeed).
        if (reference) job.settings.seed = nlosCaptureSeed(config.render.seed, c);
        return job;
      },
      [&](std::size_t c, const capture::RenderJob& job) {
        return std::make_unique<NlosCaptureSink>(out, c, perCapture, job.settings.time);
      },
      loop);
  out.vpls = stats.vpls;
  out.scenePreparations = stats.scenePreparations;
  out.device = stats.device;
  out.backend = stats.backend;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace tofsim::pipeline
