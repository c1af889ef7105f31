#include "tofsim/reference/ReferenceRenderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "PathIntegrator.h"
#include "tofsim/capture/DirectLightView.h"
#include "tofsim/capture/SegmentStream.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::reference {

using namespace capture;  // the job description types

namespace {

// The medium must be one the path tracer can sample: finite, non-negative
// coefficients, a known phase function, |g| < 1 (a Henyey-Greenstein lobe
// with |g| = 1 is a delta: no density to sample or weigh by).
void validateMedium(const Medium& m) {
  for (int c = 0; c < 3; ++c) {
    const float a = m.sigma_a_per_m[c], s = m.sigma_s_per_m[c];
    if (!(std::isfinite(a) && std::isfinite(s) && a >= 0.0f && s >= 0.0f)) {
      throw InputError("medium: sigma_a and sigma_s must be finite and >= 0 (channel " +
                       std::to_string(c) + ": sigma_a " + std::to_string(a) + ", sigma_s " +
                       std::to_string(s) + " 1/m)");
    }
  }
  if (m.phase != physics::PHASE_ISOTROPIC && m.phase != physics::PHASE_HENYEY_GREENSTEIN &&
      m.phase != physics::PHASE_RAYLEIGH) {
    throw InputError("medium: unknown phase function " + std::to_string(m.phase) +
                     " (the reference path tracer samples isotropic, henyey_greenstein, rayleigh)");
  }
  if (!(std::fabs(m.g) < 1.0f)) {
    throw InputError("medium: g must lie in (-1, 1) (got " + std::to_string(m.g) + ")");
  }
}

void validate(const ReferenceSettings& s, const RenderJob& job) {
  TOFSIM_CHECK(job.scene != nullptr);
  if (s.bounces < 1) {
    throw InputError("reference.bounces must be >= 1 (got " + std::to_string(s.bounces) + ")");
  }
  if (s.samples_per_pixel < 1) {
    throw InputError("reference.samples_per_pixel must be >= 1 (got " +
                     std::to_string(s.samples_per_pixel) + ")");
  }
  if (s.threads < 0) {
    throw InputError("reference.threads must be >= 0 (got " + std::to_string(s.threads) + ")");
  }
  if (imageWidth(job.imager) < 1 || imageHeight(job.imager) < 1) {
    throw InputError("camera resolution (or the point set) must be at least 1x1");
  }
  const TimeAxis& axis = job.settings.time;
  if (axis.bins < 1 || !(axis.bin_width_s > 0.0)) {
    throw InputError("time axis needs bins >= 1 and bin_width > 0");
  }
  validateMedium(job.settings.medium);  // also one that present() calls absent (negative)
  for (const capture::RegionMedium& r : job.settings.media) validateMedium(r.medium);
  // Its paths start at the camera's position: an aperture would be ignored.
  if (const Camera* camera = cameraOf(job.imager); camera != nullptr && camera->defocused()) {
    throw InputError("camera.aperture " + std::to_string(camera->aperture_m) +
                     " m: the reference path tracer has no thin lens (defocus runs on "
                     "render.renderer: ir with render.backend: cpu)");
  }
}

// Rows per segment: as many as the memory budget allows for the two float
// buffers, at least one; capped at a few rows per thread so progress is
// reported often and the sink can write while little is held.
int32_t rowsPerSegment(const RenderJob& job, int32_t threads) {
  const std::size_t rowBytes = static_cast<std::size_t>(imageWidth(job.imager)) *
                               job.settings.time.bins * kChannels * sizeof(float) * 2;
  const std::size_t byBudget =
      std::max<std::size_t>(1, job.settings.memory_budget_bytes / rowBytes);
  const std::size_t cap = std::max<std::size_t>(16, static_cast<std::size_t>(threads) * 4);
  return static_cast<int32_t>(
      std::min({byBudget, cap, static_cast<std::size_t>(imageHeight(job.imager))}));
}

// Pixels per work item of a segment: a row, unless there are too few rows to
// keep every thread busy (a point set is one row of points) -- then a pixel.
std::size_t pixelsPerTask(int32_t width, int32_t rows, int32_t threads) {
  return rows >= threads ? static_cast<std::size_t>(width) : 1;
}

// The light seen straight by the camera: only the first surface at its pixel
// matters, traced on demand (never for a point set: its points are surfaces).
DirectLightView lightSeenByCamera(const RenderJob& job, const RayScene& scene) {
  const PrimaryRays rays(job.imager);
  return directLightView(job, [&](int32_t x, int32_t y) -> std::optional<glm::vec3> {
    const PrimaryRay ray = rays.ray(x, y);
    const auto hit = scene.intersect(ray.origin, ray.direction);
    if (!hit) return std::nullopt;
    return hit->position_world;
  });
}

}  // namespace

ReferenceRenderer::ReferenceRenderer(ReferenceSettings settings) : settings_(settings) {}

void ReferenceRenderer::sceneChanged() const { scene_ = nullptr; }

const RayScene& ReferenceRenderer::rays(const scene::Scene& scene, int32_t threads) const {
  if (scene_ != &scene || !rays_) {
    rays_.reset();  // the old scene's device first
    rays_ = std::make_unique<RayScene>(scene, threads);
    scene_ = &scene;
    ++scenePreparations_;
  }
  return *rays_;
}

std::string ReferenceRenderer::description() const { return "CPU reference path tracer"; }

RenderResult ReferenceRenderer::render(const RenderJob& job, SegmentSink& sink,
                                       const ProgressCallback& progress) const {
  const auto started = std::chrono::steady_clock::now();
  validate(settings_, job);
  const int32_t width = imageWidth(job.imager), height = imageHeight(job.imager);
  const TimeAxis& axis = job.settings.time;
  const int32_t threads = resolveThreads(settings_.threads);
  const int32_t bounces = job.settings.indirect.enabled ? settings_.bounces : 1;

  const RayScene& rayScene = rays(*job.scene, threads);
  const PathIntegrator integrator(rayScene, job, bounces, settings_.samples_per_pixel,
                                  settings_.pixel_filter, settings_.sampling);
  const DirectLightView lightView = lightSeenByCamera(job, rayScene);

  RenderResult result;
  result.depth_m = Image(width, height, 1);
  const std::size_t pixelFloats = static_cast<std::size_t>(axis.bins) * kChannels;
  const int32_t rows = rowsPerSegment(job, threads);
  const capture::SegmentPlan plan =
      capture::fixedSegments(static_cast<std::size_t>(width) * height,
                        static_cast<std::size_t>(rows) * width, pixelFloats * 2 * sizeof(float));
  std::vector<AxisLoss> outside(static_cast<std::size_t>(width) * rows);

  capture::streamSegments(plan, axis, {kDirect, kIndirect}, lightView, sink, result.offAxis,
                     [&](const capture::SegmentBuffers& segment) {
                       // Segments are whole rows: pixelsPerSegment is a multiple of the width.
                       const int32_t firstRow = static_cast<int32_t>(segment.pixels.first / width);
                       const int32_t rowCount = static_cast<int32_t>(segment.pixels.count / width);
                       // Workers take blocks of pixels dynamically (the shared pool, which
                       // hands a worker's exception to this thread); each pixel writes only
                       // its own slots and draws from its own generator, so the bytes do not
                       // depend on scheduling or on the blocks.
                       parallelForBlocks(
                           segment.pixels.count, pixelsPerTask(width, rowCount, threads), threads,
                           [&](std::size_t begin, std::size_t end) {
                             std::vector<double> scratch;
                             for (std::size_t local = begin; local < end; ++local) {
                               const auto x = static_cast<int32_t>(local % width);
                               const auto y = firstRow + static_cast<int32_t>(local / width);
                               PixelOutput out;
                               out.direct = segment.components[0] + local * pixelFloats;
                               out.indirect = segment.components[1] + local * pixelFloats;
                               integrator.renderPixel(x, y, out, scratch);
                               result.depth_m.at(y, x, 0) = out.depth_m;
                               outside[local] = out.offAxis;
                             }
                           });
                       // Summed in pixel order, so the total is independent of the thread count.
                       for (std::size_t i = 0; i < segment.pixels.count; ++i)
                         result.offAxis += outside[i];
                       if (progress) progress(segment.index + 1, plan.segmentCount, "segments");
                     });
  result.segments = plan.segmentCount;
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace tofsim::reference
