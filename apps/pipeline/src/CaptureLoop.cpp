#include "tofsim/pipeline/CaptureLoop.h"

#include <mutex>
#include <vector>

#include "tofsim/ir/IrRenderer.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/util/Interrupt.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::pipeline {

namespace {

std::size_t preparationsOf(const RendererChoice& choice) {
  const capture::Renderer* r = choice.renderer.get();
  if (const auto* ir = dynamic_cast<const ir::IrRenderer*>(r)) return ir->scenePreparations();
  if (const auto* ref = dynamic_cast<const reference::ReferenceRenderer*>(r)) {
    return ref->scenePreparations();
  }
  return 0;
}

// The workers' renderers, one per capture in flight: the prepared one, then
// fresh ones like it made on need and kept for the loop, so that each
// prepares the scene once.
class RendererPool {
 public:
  RendererPool(PreparedRenderer& prepared, const config::RunConfig& config)
      : prepared_(prepared),
        config_(config),
        first_(&prepared.renderer(config)),
        firstBefore_(preparationsOf(*first_)) {
    free_.push_back(first_);
  }
  const RendererChoice& first() const { return *first_; }
  const RendererChoice* take() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!free_.empty()) {
        const RendererChoice* r = free_.back();
        free_.pop_back();
        return r;
      }
    }
    auto made = std::make_unique<RendererChoice>(prepared_.makeAnother(config_));
    const std::lock_guard<std::mutex> lock(mutex_);
    made_.push_back(std::move(made));
    return made_.back().get();
  }
  void give(const RendererChoice* r) {
    const std::lock_guard<std::mutex> lock(mutex_);
    free_.push_back(r);
  }
  std::size_t preparations() const {
    std::size_t n = preparationsOf(*first_) - firstBefore_;
    for (const auto& r : made_) n += preparationsOf(*r);
    return n;
  }
  std::size_t renderers() const { return 1 + made_.size(); }

 private:
  PreparedRenderer& prepared_;
  const config::RunConfig& config_;
  const RendererChoice* first_;
  std::size_t firstBefore_;
  std::mutex mutex_;
  std::vector<const RendererChoice*> free_;
  std::vector<std::unique_ptr<RendererChoice>> made_;
};

// A renderer taken from the pool for one capture, given back however it ends.
class Taken {
 public:
  explicit Taken(RendererPool& pool) : pool_(pool), choice_(pool.take()) {}
  ~Taken() { pool_.give(choice_); }
  Taken(const Taken&) = delete;
  Taken& operator=(const Taken&) = delete;
  const RendererChoice& operator*() const { return *choice_; }

 private:
  RendererPool& pool_;
  const RendererChoice* choice_;
};

}  // namespace

CaptureLoopStats renderCaptures(PreparedRenderer& prepared, const config::RunConfig& rendererConfig,
                                std::size_t count, const CaptureJobOf& jobOf,
                                const CaptureSinkOf& sinkOf, const CaptureLoopOptions& options) {
  RendererPool pool(prepared, rendererConfig);
  CaptureLoopStats stats;
  stats.backend = pool.first().backend;
  stats.device = pool.first().renderer->description();
  const int workers = options.workers > 1 && count > 1 ? options.workers : 1;
  const capture::ProgressCallback& within =
      workers == 1 ? options.withinCapture : capture::ProgressCallback{};
  std::mutex doneMutex;
  parallelFor(count, workers, [&](std::size_t i) {
    throwIfInterrupted();
    const capture::RenderJob job = jobOf(i);
    const std::unique_ptr<CaptureSink> sink = sinkOf(i, job);
    const Taken renderer(pool);
    const capture::RenderResult result =
        (*renderer).renderer->render(job, sink->segments(), within);
    throwIfInterrupted();  // a signal during the last segment still means "stop"
    sink->finish(result, *renderer);
    const std::lock_guard<std::mutex> lock(doneMutex);
    ++stats.captures;
    stats.vpls += result.vpls;
    if (options.captureDone) options.captureDone(stats.captures, count, options.unit);
  });
  stats.scenePreparations = pool.preparations();
  stats.renderers = pool.renderers();
  return stats;
}

}  // namespace tofsim::pipeline
