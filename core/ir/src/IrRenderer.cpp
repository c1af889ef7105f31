#include "tofsim/ir/IrRenderer.h"

#include <chrono>

#include "JobValidation.h"
#include "MemoryPlan.h"
#include "tofsim/capture/DirectLightView.h"
#include "tofsim/ir/BounceVpls.h"
#include "tofsim/ir/SegmentStream.h"
#include "tofsim/util/Error.h"

namespace tofsim::ir {

using namespace capture;  // the job description types

namespace {

Image depthFromPositions(const std::vector<float>& positions, const Camera& camera) {
  Image depth(camera.width, camera.height, 1);
  for (int32_t y = 0; y < camera.height; ++y) {
    for (int32_t x = 0; x < camera.width; ++x) {
      const float* p = &positions[(static_cast<std::size_t>(y) * camera.width + x) * 4];
      if (p[3] == 0.0f) continue;
      depth.at(y, x, 0) = glm::length(glm::vec3(p[0], p[1], p[2]) - camera.position_world);
    }
  }
  return depth;
}

// One segment: the direct gather, then every VPL batch in increasing order
// (building its visibility unless it is still resident), then the read-back.
class SegmentPasses {
 public:
  SegmentPasses(IrBackend& backend, const MemoryPlan& plan, std::size_t vplCount,
                const ProgressCallback& progress, AxisLoss& offAxis)
      : backend_(backend),
        plan_(plan),
        vplCount_(vplCount),
        progress_(progress),
        offAxis_(offAxis) {}

  void operator()(const SegmentBuffers& buffers) {
    const std::size_t workUnits = plan_.segments.segmentCount * (1 + plan_.batchCount);
    std::size_t done = buffers.index * (1 + plan_.batchCount);
    backend_.beginSegment(buffers.pixels.first, buffers.pixels.count);
    backend_.gatherDirect();
    if (progress_) progress_(++done, workUnits, "segment/VPL-batch passes");
    for (std::size_t b = 0; b < plan_.batchCount; ++b) {
      const std::size_t first = b * plan_.vplsPerBatch;
      const std::size_t count = std::min(plan_.vplsPerBatch, vplCount_ - first);
      // Every segment needs every batch; a single batch is built once and kept.
      if (residentBatch_ != b) backend_.buildVisibility(first, count);
      residentBatch_ = b;
      backend_.gatherIndirect(first, count);
      if (progress_) progress_(++done, workUnits, "segment/VPL-batch passes");
    }
    backend_.readSegment(buffers.components[0], buffers.components[1], offAxis_);
  }

 private:
  IrBackend& backend_;
  const MemoryPlan& plan_;
  std::size_t vplCount_;
  const ProgressCallback& progress_;
  AxisLoss& offAxis_;
  std::size_t residentBatch_ = static_cast<std::size_t>(-1);
};

}  // namespace

IrRenderer::IrRenderer(std::unique_ptr<IrBackend> backend) : backend_(std::move(backend)) {
  TOFSIM_CHECK(backend_ != nullptr);
}

std::string IrRenderer::description() const { return backend_->description(); }

RenderResult IrRenderer::render(const RenderJob& job, SegmentSink& sink,
                                const ProgressCallback& progress) const {
  const auto started = std::chrono::steady_clock::now();
  IrBackend& backend = *backend_;
  const DeviceLimits limits = backend.limits();
  validateJob(job, limits);
  RenderResult result;

  const std::vector<float> positions = backend.prepareSurfaces(job);
  TOFSIM_CHECK_EQ(positions.size(),
                  static_cast<std::size_t>(job.camera.width) * job.camera.height * 4);
  result.depth_m = depthFromPositions(positions, job.camera);
  // Bounce 1 from the backend's RSM, later bounces traced from it here, so
  // both backends gather the same VPLs of every bounce; bounced.firstOfBounce
  // keeps which VPLs are of which bounce (for bounce-resolved output).
  const BouncedVpls bounced = withLaterBounces(job, backend.generateVpls(job));
  const std::vector<Vpl>& vpls = bounced.vpls;
  backend.setVpls(vpls);

  const MemoryPlan plan =
      planMemory(job, limits, backend.fixedBytes(), vpls.size(), backend.visibilityBytesPerVpl());
  result.segments = plan.segments.segmentCount;
  result.vpls = vpls.size();
  result.vplBatches = plan.batchCount;
  result.peakGpuBytes = plan.peakBytes;
  backend.allocate(plan.segments.pixelsPerSegment, plan.vplsPerBatch);

  const DirectLightView lightView = directLightView(job, positions);
  SegmentPasses passes(backend, plan, vpls.size(), progress, result.offAxis);
  streamSegments(plan.segments, job.settings.time, {kDirect, kIndirect}, lightView, sink,
                 result.offAxis, std::ref(passes));
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace tofsim::ir
