#include "tofsim/pipeline/NlosRender.h"

#include <chrono>
#include <memory>
#include <mutex>

#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/pipeline/RendererFactory.h"
#include "tofsim/util/Interrupt.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::pipeline {

namespace {

// Fewer points per capture than this: parallel over captures instead.
constexpr std::size_t kPointsForParallelGather = 256;

// Renderers handed to the workers, each made on first need and kept, so each
// prepares the scene once.
class RendererPool {
 public:
  RendererPool(int backendThreads) : backendThreads_(backendThreads) {}
  std::unique_ptr<ir::IrRenderer> take() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!free_.empty()) {
        auto r = std::move(free_.back());
        free_.pop_back();
        return r;
      }
    }
    return std::make_unique<ir::IrRenderer>(
        makeIrBackend(config::IrBackendKind::Cpu, gl::EglPlatform::Auto, backendThreads_));
  }
  void give(std::unique_ptr<ir::IrRenderer> r) {
    const std::lock_guard<std::mutex> lock(mutex_);
    free_.push_back(std::move(r));
  }
  std::size_t scenePreparations() const {
    std::size_t n = 0;
    for (const auto& r : free_) n += r->scenePreparations();
    return n;
  }
  std::string description() const { return free_.empty() ? "" : free_.front()->description(); }

 private:
  int backendThreads_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<ir::IrRenderer>> free_;
};

}  // namespace

NlosVolume renderNlosScan(const config::RunConfig& config, const scene::Scene& scene,
                          const NlosScanGeometry& scan, const capture::ProgressCallback& progress) {
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

  const int threads = resolveThreads(config.cpu_threads);
  const bool overCaptures = perCapture < kPointsForParallelGather && out.captures > 1;
  const int workers = overCaptures ? threads : 1;
  const int backendThreads = overCaptures ? 1 : threads;
  RendererPool pool(backendThreads);
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
    capture::VolumeCollector collector(static_cast<int32_t>(perCapture), 1, job.settings.time,
                                       capture::kChannels);
    std::unique_ptr<ir::IrRenderer> renderer = pool.take();
    const capture::RenderResult result = renderer->render(job, collector);
    pool.give(std::move(renderer));
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
