#include "tofsim/pipeline/NlosRender.h"

#include <chrono>
#include <memory>
#include <mutex>

#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/pipeline/RendererFactory.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/util/Interrupt.h"
#include "tofsim/util/ParallelFor.h"
#include "tofsim/util/Random.h"

namespace tofsim::pipeline {

namespace {

// Fewer points per capture than this: parallel over captures instead.
constexpr std::size_t kPointsForParallelGather = 256;

reference::ReferenceSettings referenceSettings(const config::RunConfig& config, int threads) {
  reference::ReferenceSettings settings = makeReferenceSettings(config.reference);
  settings.threads = threads;
  return settings;
}

// One worker's renderer, IR over its backend or the reference path tracer,
// made on first need and kept, so that it prepares the scene once.
struct Worker {
  std::unique_ptr<ir::IrRenderer> ir;
  std::unique_ptr<reference::ReferenceRenderer> reference;
  const capture::Renderer& renderer() const {
    if (ir) return *ir;
    return *reference;
  }
  std::size_t scenePreparations() const {
    return ir ? ir->scenePreparations() : reference->scenePreparations();
  }
};

// The workers' renderers, handed out one per running capture.
class RendererPool {
 public:
  RendererPool(const config::RunConfig& config, config::IrBackendKind backend,
               gl::EglPlatform eglPlatform, int rendererThreads)
      : config_(config),
        backend_(backend),
        eglPlatform_(eglPlatform),
        rendererThreads_(rendererThreads) {}
  Worker take() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!free_.empty()) {
        Worker w = std::move(free_.back());
        free_.pop_back();
        return w;
      }
    }
    Worker w;
    if (config_.renderer == config::RendererKind::Reference) {
      w.reference = std::make_unique<reference::ReferenceRenderer>(
          referenceSettings(config_, rendererThreads_));
    } else {
      w.ir =
          std::make_unique<ir::IrRenderer>(makeIrBackend(backend_, eglPlatform_, rendererThreads_));
    }
    return w;
  }
  void give(Worker w) {
    const std::lock_guard<std::mutex> lock(mutex_);
    free_.push_back(std::move(w));
  }
  std::size_t scenePreparations() const {
    std::size_t n = 0;
    for (const auto& w : free_) n += w.scenePreparations();
    return n;
  }
  std::string description() const {
    return free_.empty() ? "" : free_.front().renderer().description();
  }

 private:
  const config::RunConfig& config_;
  config::IrBackendKind backend_;
  gl::EglPlatform eglPlatform_;
  int rendererThreads_;
  std::mutex mutex_;
  std::vector<Worker> free_;
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
  const auto start = std::chrono::steady_clock::now();
  NlosVolume out;
  out.axis = config.render.time;
  out.captures = scan.captureCount();
  const std::size_t perCapture = scan.pointsPerCapture();
  const std::size_t points = out.captures * perCapture;
  const auto bins = static_cast<std::size_t>(out.axis.bins);
  out.shape = {bins};
  for (std::size_t n : scan.pointShape()) out.shape.push_back(n);
  out.H.assign(bins * points, 0.0f);

  const bool reference = config.renderer == config::RendererKind::Reference;
  const int threads = resolveThreads(reference ? config.reference.threads : config.cpu_threads);
  const config::IrBackendKind backend =
      reference ? config::IrBackendKind::Cpu : resolveIrBackend(config.backend);
  out.backend = reference ? "reference" : config::irBackendName(backend);
  // One GL context, current on this thread: its captures one after another.
  const bool gl = backend == config::IrBackendKind::Gl;
  const bool overCaptures = !gl && perCapture < kPointsForParallelGather && out.captures > 1;
  const int workers = overCaptures ? threads : 1;
  const int backendThreads = overCaptures ? 1 : threads;
  RendererPool pool(config, backend, eglPlatform, backendThreads);
  std::mutex progressMutex;
  std::size_t done = 0, vpls = 0;

  parallelFor(out.captures, workers, [&](std::size_t c) {
    throwIfInterrupted();
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
    capture::VolumeCollector collector(static_cast<int32_t>(perCapture), 1, job.settings.time,
                                       capture::kChannels);
    Worker worker = pool.take();
    const capture::RenderResult result = worker.renderer().render(job, collector);
    pool.give(std::move(worker));
    // H[t, point] = R + G + B of the indirect light (tal render's sum).
    const float* v = collector.indirect.data();
    for (std::size_t k = 0; k < perCapture; ++k) {
      const std::size_t point = c * perCapture + k;
      for (std::size_t t = 0; t < bins; ++t) {
        const float* rgb = v + (k * bins + t) * capture::kChannels;
        out.H[t * points + point] = rgb[0] + rgb[1] + rgb[2];
      }
    }
    const std::lock_guard<std::mutex> lock(progressMutex);
    vpls += result.vpls;
    ++done;
    if (progress) progress(done, out.captures, "laser positions");
  });
  out.vpls = vpls;
  out.scenePreparations = pool.scenePreparations();
  out.device = pool.description();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace tofsim::pipeline
