#include "tofsim/ir/IrRenderer.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "JobValidation.h"
#include "MemoryPlan.h"
#include "tofsim/capture/DirectLightView.h"
#include "tofsim/capture/RegionScattering.h"
#include "tofsim/capture/SegmentStream.h"
#include "tofsim/ir/BounceVpls.h"
#include "tofsim/ir/LitPixels.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/ir/SampledPixels.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/ir/VplClasses.h"
#include "tofsim/physics/ResponseClassTable.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/util/Error.h"

namespace tofsim::ir {

using namespace capture;  // the job description types

namespace {

Image depthFromPositions(const std::vector<float>& positions, const Imager& imager) {
  const int32_t width = imageWidth(imager), height = imageHeight(imager);
  // Along each pixel's centre ray, from where it starts (the viewpoint, or
  // the ray's own origin).
  const PrimaryRays rays(imager);
  Image depth(width, height, 1);
  for (int32_t y = 0; y < height; ++y) {
    for (int32_t x = 0; x < width; ++x) {
      const float* p = &positions[(static_cast<std::size_t>(y) * width + x) * 4];
      if (p[3] == 0.0f) continue;
      depth.at(y, x, 0) = glm::length(glm::vec3(p[0], p[1], p[2]) - rays.ray(x, y).origin);
    }
  }
  return depth;
}

// One gatherIndirect: VPLs [first, first + count), all of bounce `bounce`
// (0-based) and of the memory plan's visibility batch `batch`.
struct GatherStep {
  std::size_t first = 0;
  std::size_t count = 0;
  std::size_t bounce = 0;
  std::size_t batch = 0;
};

// The memory plan's visibility batches (vplsPerBatch VPLs each, in VPL
// order), each cut where a bounce ends, so each bounce's light can be read
// out alone while every batch is still built once per segment (once per
// render when it is the only one). With one bounce the steps are the batches.
std::vector<GatherStep> planGathers(const BouncedVpls& bounced, std::size_t vplsPerBatch) {
  std::vector<GatherStep> steps;
  if (vplsPerBatch == 0) return steps;  // no VPLs
  for (std::size_t k = 0; k + 1 < bounced.firstOfBounce.size(); ++k) {
    const std::size_t end = bounced.firstOfBounce[k + 1];
    for (std::size_t first = bounced.firstOfBounce[k]; first < end;) {
      const std::size_t batch = first / vplsPerBatch;
      const std::size_t stop = std::min(end, (batch + 1) * vplsPerBatch);
      steps.push_back({first, stop - first, k, batch});
      first = stop;
    }
  }
  return steps;
}

// The response classes of a render of `job` (core/physics/temporal_response.md):
// the scene's distinct scattering delays, on paths of up to one delayed vertex
// per VPL bounce plus the pixel's own surface, started by the light's own
// surface's (an NLOS laser spot's relay wall). A scene without delays gets the
// table of the instant class alone (nothing allocated, the bytes of before).
physics::ResponseClassTable responseClassesOf(const RenderJob& job) {
  try {
    MaterialResponses responses = materialResponses(*job.scene);
    const uint32_t start = lightResponse(responses, job.light);
    return responseClasses(std::move(responses.kernels), job.settings.indirect, start);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string(e.what()) +
                     ": lower render.indirect.bounces or give fewer materials a scattering_delay");
  }
}

// Adds the wall seconds since the last lap (or construction) to a pass's sum.
class PassClock {
 public:
  void lap(double& seconds) {
    const auto now = std::chrono::steady_clock::now();
    seconds += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }
  void restart() { last_ = std::chrono::steady_clock::now(); }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// One segment: the direct gather, then every VPL batch in increasing order
// (building its visibility unless it is still resident), then the read-back.
// With several bounces, each bounce's light is read out after its batches
// (buffers.components[2 + k] for bounce k + 1) and indirect is their float
// sum in bounce order, so indirect = sum of the bounces exactly.
class SegmentPasses {
 public:
  SegmentPasses(IrBackend& backend, const MemoryPlan& plan, std::size_t vplCount,
                std::size_t floatsPerPixel, std::vector<GatherStep> steps, std::size_t bounces,
                const ProgressCallback& progress, AxisLoss& offAxis, PassSeconds& passSeconds)
      : backend_(backend),
        plan_(plan),
        vplCount_(vplCount),
        floatsPerPixel_(floatsPerPixel),
        steps_(std::move(steps)),
        bounces_(bounces),
        progress_(progress),
        offAxis_(offAxis),
        seconds_(passSeconds) {}

  void operator()(const SegmentBuffers& buffers) {
    const std::size_t workUnits = plan_.segments.segmentCount * (1 + steps_.size());
    std::size_t done = buffers.index * (1 + steps_.size());
    PassClock clock;
    backend_.beginSegment(buffers.pixels.first, buffers.pixels.count);
    clock.lap(seconds_.readBack);  // clearing the accumulators, when needed
    backend_.gatherDirect();
    clock.lap(seconds_.direct);
    if (progress_) progress_(++done, workUnits, "segment/VPL-batch passes");
    const bool resolved = bounces_ > 1;
    std::size_t b = 0;
    for (std::size_t k = 0; k < bounces_; ++k) {
      for (; b < steps_.size() && steps_[b].bounce == k; ++b) {
        const GatherStep& step = steps_[b];
        // Every segment needs every batch; a single batch is built once and kept.
        if (residentBatch_ != step.batch) {
          const std::size_t first = step.batch * plan_.vplsPerBatch;
          backend_.buildVisibility(first, std::min(plan_.vplsPerBatch, vplCount_ - first));
          clock.lap(seconds_.visibility);
        }
        residentBatch_ = step.batch;
        backend_.gatherIndirect(step.first, step.count);
        clock.lap(seconds_.indirect);
        if (progress_) progress_(++done, workUnits, "segment/VPL-batch passes");
        clock.restart();  // the progress callback is not a pass
      }
      if (resolved && k + 1 < bounces_) backend_.takeIndirect(buffers.components[2 + k]);
      clock.lap(seconds_.readBack);
    }
    float* lastIndirect = buffers.components[resolved ? 1 + bounces_ : 1];
    backend_.readSegment(buffers.components[0], lastIndirect, offAxis_);
    if (resolved) sumBounces(buffers);
    clock.lap(seconds_.readBack);
  }

 private:
  void sumBounces(const SegmentBuffers& buffers) const {
    const std::size_t floats = buffers.pixels.count * floatsPerPixel_;
    float* indirect = buffers.components[1];
    std::copy_n(buffers.components[2], floats, indirect);
    for (std::size_t k = 1; k < bounces_; ++k) {
      const float* bounce = buffers.components[2 + k];
      for (std::size_t i = 0; i < floats; ++i) indirect[i] += bounce[i];
    }
  }

  IrBackend& backend_;
  const MemoryPlan& plan_;
  std::size_t vplCount_;
  std::size_t floatsPerPixel_;  ///< bins * kChannels
  std::vector<GatherStep> steps_;
  std::size_t bounces_;
  const ProgressCallback& progress_;
  AxisLoss& offAxis_;
  PassSeconds& seconds_;
  std::size_t residentBatch_ = static_cast<std::size_t>(-1);
};

// With one bounce the indirect light is bounce 1's: the segment names it
// twice ("bounce1" = "indirect") rather than copying it.
class SingleBounceAlias : public SegmentSink {
 public:
  explicit SingleBounceAlias(SegmentSink& next) : next_(next) {}
  void consume(const Segment& segment) override {
    Segment aliased = segment;
    aliased.components.push_back({bounceComponent(1), segment.component(kIndirect)});
    next_.consume(aliased);
  }

 private:
  SegmentSink& next_;
};

}  // namespace

IrRenderer::IrRenderer(std::unique_ptr<IrBackend> backend) : backend_(std::move(backend)) {
  TOFSIM_CHECK(backend_ != nullptr);
}

IrRenderer::~IrRenderer() = default;

void IrRenderer::sceneChanged() const { scene_ = nullptr; }

const rays::RayScene& IrRenderer::rays() const {
  TOFSIM_CHECK(scene_ != nullptr);
  if (!rays_) rays_ = std::make_unique<rays::RayScene>(*scene_, 0);
  return *rays_;
}

void IrRenderer::prepareScene(const scene::Scene& scene) const {
  rays_.reset();  // the old scene's; built again only when something traces
  scene_ = &scene;
  backend_->setScene(scene, backend_->tracesRays() ? &rays() : nullptr);
  ++scenePreparations_;
}

std::string IrRenderer::description() const { return backend_->description(); }

RenderResult IrRenderer::render(const RenderJob& job, SegmentSink& sink,
                                const ProgressCallback& progress) const {
  const auto started = std::chrono::steady_clock::now();
  IrBackend& backend = *backend_;
  const DeviceLimits limits = backend.limits();
  validateJob(job, limits);
  const capture::IrCapabilities need = capture::irNeeds(cameraOf(job.imager), job.settings);
  if (need.defocus && !backend.capabilities().defocus) {
    throw InputError("camera.aperture " + std::to_string(cameraOf(job.imager)->aperture_m) +
                     " m: defocus (thin-lens aperture sampling) runs on render.backend: cpu; the " +
                     backend.description() +
                     " backend does not gather aperture samples (set camera.aperture: 0)");
  }
  if (need.merged_pixel_samples && !backend.capabilities().merged_pixel_samples) {
    throw InputError("render.indirect.merge_pixel_samples runs on render.backend: cpu; the " +
                     backend.description() + " backend gathers every pixel sample");
  }
  // A scattering region's passes trace a ray per node along the camera rays
  // (shadow rays, the regions' passages): the backend that traces rays.
  if (regionsScatter(job.settings) && !backend.tracesRays()) {
    throw InputError("a scattering region (media: sigma_s > 0) runs on render.backend: cpu; the " +
                     backend.description() + " backend does not scatter light in regions");
  }
  if (need.sampled_gather && !backend.capabilities().sampled_gather) {
    throw InputError("render.indirect.gather_pairs runs on render.backend: cpu; the " +
                     backend.description() + " backend gathers every (pixel, VPL) pair");
  }
  RenderResult result;

  PassClock clock;
  if (job.scene != scene_) prepareScene(*job.scene);
  // Before the VPLs: each VPL's class (Vpl::flux.w) is made with them.
  const physics::ResponseClassTable classes = responseClassesOf(job);
  backend.setResponseClasses(classes);
  if (pinhole(job.imager) == nullptr && !backend.tracesRays()) {
    // What a rasterizer cannot draw, the driver traces (the same rays the
    // CPU backend traces for itself) and the backend gathers from.
    const int threads = job.settings.indirect.trace_threads;
    const int32_t n = job.settings.pixel_samples;
    const int model = vertexModelOf(job.settings.materials);
    auto samples =
        std::make_unique<SurfaceImage>(traceSurfaces(rays(), job.imager, threads, n, 1, model));
    std::unique_ptr<SurfaceImage> centres;
    if (n > 1)
      centres =
          std::make_unique<SurfaceImage>(traceSurfaces(rays(), job.imager, threads, 1, 1, model));
    backend.setSurfaces(std::move(samples), std::move(centres));
  }
  const CentreSurfaces centres = backend.prepareSurfaces(job);
  const std::vector<float>& positions = centres.positions;
  const int32_t width = imageWidth(job.imager), height = imageHeight(job.imager);
  TOFSIM_CHECK_EQ(positions.size(), static_cast<std::size_t>(width) * height * 4);
  result.depth_m = depthFromPositions(positions, job.imager);
  if (job.settings.adaptive_pixel_samples && job.settings.pixel_samples > 1) {
    // Shadow edges and a spot's rim inside flat pixels too, by the driver's
    // rays whatever the backend (LitPixels.h).
    const std::vector<uint8_t> sampled = adaptiveSampledPixels(centres, job, rays());
    result.sampledPixels = static_cast<std::size_t>(std::count(sampled.begin(), sampled.end(), 1));
    backend.setSampledPixels(sampled);
  }
  clock.lap(result.passSeconds.surfaces);
  // Bounce 1 from the backend's RSM, later bounces traced from it here, so
  // both backends gather the same VPLs of every bounce; bounced.firstOfBounce
  // keeps which VPLs are of which bounce (for bounce-resolved output).
  const capture::IndirectSettings& indirect = job.settings.indirect;
  const BouncedVpls bounced = indirect.bounces > 1 || lightMediumVplsWanted(job.settings)
                                  ? withLaterBounces(job, rays(), backend.generateVpls(job), &classes)
                                  : withLaterBounces(job, backend.generateVpls(job), &classes);
  const std::vector<Vpl>& vpls = bounced.vpls;
  backend.setVpls(vpls);
  clock.lap(result.passSeconds.vpls);

  // The response classes' buffers are per pixel: the plan counts them.
  const MemoryPlan plan =
      planMemory(job, limits, backend.fixedBytes(), vpls.size(), backend.visibilityBytesPerVpl(),
                 physics::responseBuffers(classes));
  result.segments = plan.segments.segmentCount;
  result.vpls = vpls.size();
  result.vplBatches = plan.batchCount;
  result.peakGpuBytes = plan.peakBytes;
  backend.allocate(plan.segments.pixelsPerSegment, plan.vplsPerBatch);

  const DirectLightView lightView = directLightView(job, positions);
  const auto bounces = static_cast<std::size_t>(bounced.bounces());
  SegmentPasses passes(backend, plan, vpls.size(),
                       static_cast<std::size_t>(job.settings.time.bins) * kChannels,
                       planGathers(bounced, plan.vplsPerBatch), bounces, progress, result.offAxis,
                       result.passSeconds);
  std::vector<std::string_view> names = {kDirect, kIndirect};
  if (bounces > 1) {
    for (std::size_t k = 1; k <= bounces; ++k)
      names.push_back(bounceComponent(static_cast<int32_t>(k)));
    streamSegments(plan.segments, job.settings.time, names, lightView, sink, result.offAxis,
                   std::ref(passes));
  } else {
    SingleBounceAlias aliased(sink);
    streamSegments(plan.segments, job.settings.time, names, lightView, aliased, result.offAxis,
                   std::ref(passes));
  }
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  PassSeconds& s = result.passSeconds;
  s.other = std::max(0.0, result.seconds - (s.surfaces + s.vpls + s.visibility + s.direct +
                                            s.indirect + s.readBack));
  return result;
}

}  // namespace tofsim::ir
