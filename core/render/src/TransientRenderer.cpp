#include "tofsim/render/TransientRenderer.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <cmath>
#include <vector>

#include "GpuScene.h"
#include "IndirectLight.h"
#include "LightShadowMap.h"
#include "LightUniforms.h"
#include "SegmentPlan.h"
#include "SurfaceMaps.h"
#include "tofsim/capture/DirectLightView.h"
#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Check.h"
#include "tofsim/gl/Compute.h"
#include "tofsim/gl/Context.h"
#include "tofsim/util/Error.h"

namespace tofsim::render {

using namespace capture;  // the job description types

namespace {

constexpr int kChannels = 3;
constexpr uint32_t kWorkGroupSize = 64;  // local_size_x of the gather shaders

// Everything that can be checked against the GL implementation's limits
// before any GL work; each message names the config key to change.
void validateJob(const RenderJob& job, const gl::ContextLimits& limits) {
  TOFSIM_CHECK(job.scene != nullptr);
  const Camera& c = job.camera;
  const std::string maxTexture = std::to_string(limits.maxTextureSize);
  if (c.width > limits.maxTextureSize || c.height > limits.maxTextureSize) {
    throw InputError("camera.resolution " + std::to_string(c.width) + "x" +
                     std::to_string(c.height) + " exceeds the GL implementation's texture limit " +
                     maxTexture);
  }
  if (job.settings.shadow_map_resolution > limits.maxTextureSize) {
    throw InputError("render.shadow_map_resolution " +
                     std::to_string(job.settings.shadow_map_resolution) +
                     " exceeds the GL texture limit " + maxTexture);
  }
  const IndirectSettings& s = job.settings.indirect;
  if (s.enabled && s.rsm_resolution > limits.maxTextureSize) {
    throw InputError("render.indirect.rsm_resolution " + std::to_string(s.rsm_resolution) +
                     " exceeds the GL texture limit " + maxTexture);
  }
  // One ISM (without its pull-push pyramid) is one storage block.
  const std::size_t ismBytes = std::size_t(s.ism_resolution) * s.ism_resolution * sizeof(float);
  if (s.enabled && ismBytes > limits.maxShaderStorageBlockBytes) {
    throw InputError("render.indirect.ism_resolution " + std::to_string(s.ism_resolution) +
                     " needs " + std::to_string(ismBytes) +
                     " bytes per VPL, over the GL storage-block limit " +
                     std::to_string(limits.maxShaderStorageBlockBytes));
  }
  const std::size_t pixelBytes = std::size_t(job.settings.time.bins) * kChannels * sizeof(float);
  if (pixelBytes > limits.maxShaderStorageBlockBytes) {
    throw InputError("time.bins " + std::to_string(job.settings.time.bins) + " x " +
                     std::to_string(kChannels) + " channels x 4 bytes exceeds the GL " +
                     "storage-block limit " + std::to_string(limits.maxShaderStorageBlockBytes) +
                     " bytes; use fewer time bins");
  }
}

// Scene bounds grown to hold the camera and the light, for depth ranges.
void viewBounds(const RenderJob& job, glm::vec3& lo, glm::vec3& hi) {
  const scene::Bounds b = job.scene->bounds();
  lo = glm::min(glm::min(b.min, job.camera.position_world), job.light.position_world);
  hi = glm::max(glm::max(b.max, job.camera.position_world), job.light.position_world);
}

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

// Uniforms shared by the direct and indirect gathers: image, time axis, camera.
void configureGather(const gl::Program& program, const RenderJob& job) {
  const TimeAxis& axis = job.settings.time;
  program.set("uImageWidth", job.camera.width);
  program.set("uBins", axis.bins);
  program.set("uStart_m", static_cast<float>(axis.start_m()));
  program.set("uBinWidth_m", static_cast<float>(axis.bin_width_m()));
  program.set("uIndexOfRefraction", static_cast<float>(job.settings.index_of_refraction));
  program.set("uCameraUnwarp", job.settings.camera_unwarp ? 1 : 0);
  program.set("uCameraPosition_world", job.camera.position_world);
  const glm::vec3 extent = job.scene->bounds().max - job.scene->bounds().min;
  program.set("uSceneScale_m", std::max(glm::length(extent), 1e-6f));
  program.set("uGeometryClamp", static_cast<float>(job.settings.indirect.geometry_term_clamp_per_m2));
}

// VPLs and their visibility structures, or null when indirect light is off
// or no VPL receives light.
std::unique_ptr<IndirectLight> makeIndirectLight(const RenderJob& job, const GpuScene& gpuScene,
                                                 const glm::vec3& lo, const glm::vec3& hi) {
  const capture::IndirectSettings& s = job.settings.indirect;
  if (!s.enabled) return nullptr;
  std::vector<Vpl> vpls = generateVpls(gpuScene, job.light, s.rsm_resolution,
                                       job.settings.index_of_refraction, lo, hi);
  if (vpls.empty()) return nullptr;
  return std::make_unique<IndirectLight>(scene::buildTriangleSoup(*job.scene), std::move(vpls), s,
                                         job.settings.seed);
}

}  // namespace

TransientRenderer::TransientRenderer(gl::Context& context) : context_(context) {}

RenderResult TransientRenderer::render(const RenderJob& job, SegmentSink& sink,
                                       const ProgressCallback& progress) const {
  const auto started = std::chrono::steady_clock::now();
  const gl::ContextLimits& limits = context_.limits();
  validateJob(job, limits);
  const Camera& camera = job.camera;
  const RenderSettings& settings = job.settings;
  const TimeAxis& axis = settings.time;
  RenderResult result;

  GpuScene gpuScene(*job.scene);
  glm::vec3 lo, hi;
  viewBounds(job, lo, hi);

  SurfaceMaps gbuffer(camera.width, camera.height);
  const glm::vec2 range = depthRange(lo, hi, camera.position_world);
  gbuffer.render(gpuScene, camera.projection(range.x, range.y) * camera.view(),
                 camera.position_world);
  const std::size_t pixelCount = static_cast<std::size_t>(camera.width) * camera.height;
  std::vector<float> positions(pixelCount * 4);
  gbuffer.position.download(GL_RGBA, GL_FLOAT, positions.size() * sizeof(float), positions.data());
  result.depth_m = depthFromPositions(positions, camera);

  LightShadowMap shadowMap(settings.shadow_map_resolution, job.light.position_world, lo, hi);
  shadowMap.render(gpuScene);

  gl::Program directGather({{GL_COMPUTE_SHADER, "direct_gather.comp"}});
  setLightUniforms(directGather, job.light);
  shadowMap.bind(directGather);
  configureGather(directGather, job);

  std::unique_ptr<IndirectLight> indirectLight = makeIndirectLight(job, gpuScene, lo, hi);
  std::size_t fixedBytes = gpuScene.bytes() + pixelCount * 4 * 4 * sizeof(float) + shadowMap.bytes();
  if (indirectLight) fixedBytes += indirectLight->fixedBytes();
  if (fixedBytes >= settings.memory_budget_bytes) {
    throw InputError("render.memory_budget (" + std::to_string(settings.memory_budget_bytes) +
                     " bytes) does not exceed what the scene, G-buffer, shadow map and VPLs "
                     "need (" + std::to_string(fixedBytes) + " bytes) before any volume "
                     "segment; raise render.memory_budget");
  }
  std::size_t budget = settings.memory_budget_bytes - fixedBytes;  // > 0, checked above
  if (indirectLight) {
    // ISM batches get what all ISMs need, up to half of what is left; the
    // volume segments get the rest.
    const std::size_t allIsms = indirectLight->ismBytesPerVpl() * indirectLight->vplCount();
    const std::size_t ismBudget = std::min(allIsms, budget / 2);
    indirectLight->planBatches(ismBudget, limits.maxShaderStorageBlockBytes);
    budget -= indirectLight->ismBatchBytes();
    result.vpls = indirectLight->vplCount();
    result.vplBatches = indirectLight->batchCount();
    configureGather(indirectLight->gatherProgram(), job);
  }
  const std::size_t floatsPerPixel = static_cast<std::size_t>(axis.bins) * kChannels;
  const std::size_t maxDispatchPixels =
      static_cast<std::size_t>(limits.maxComputeWorkGroupCount[0]) * kWorkGroupSize;
  const SegmentPlan plan = planSegments(pixelCount, floatsPerPixel, 2, budget,
                                        limits.maxShaderStorageBlockBytes, maxDispatchPixels);
  result.segments = plan.segmentCount;
  result.peakGpuBytes = settings.memory_budget_bytes - budget + plan.bytesPerSegment;
  const std::size_t batches = indirectLight ? indirectLight->batchCount() : 0;
  const std::size_t workUnits = plan.segmentCount * (1 + batches);

  const std::size_t segmentFloats = plan.pixelsPerSegment * floatsPerPixel;
  gl::Buffer directBuffer(segmentFloats * sizeof(float));
  gl::Buffer indirectBuffer(segmentFloats * sizeof(float));
  // Per pixel: light before the axis, light after it.
  gl::Buffer outsideBuffer(plan.pixelsPerSegment * 2 * sizeof(float));
  std::vector<float> direct(segmentFloats), indirect(segmentFloats),
      outside(plan.pixelsPerSegment * 2);

  const DirectLightView lightView = directLightView(job, positions);
  for (std::size_t s = 0; s < plan.segmentCount; ++s) {
    const std::size_t first = s * plan.pixelsPerSegment;
    const std::size_t count = std::min(plan.pixelsPerSegment, pixelCount - first);
    const std::size_t floats = count * floatsPerPixel;
    directBuffer.clear();
    indirectBuffer.clear();
    outsideBuffer.clear();
    directBuffer.bindRange(GL_SHADER_STORAGE_BUFFER, 0, 0, floats * sizeof(float));
    indirectBuffer.bindRange(GL_SHADER_STORAGE_BUFFER, 1, 0, floats * sizeof(float));
    outsideBuffer.bindRange(GL_SHADER_STORAGE_BUFFER, 2, 0, count * 2 * sizeof(float));

    gbuffer.position.bindUnit(0);
    gbuffer.normal.bindUnit(1);
    gbuffer.albedo.bindUnit(2);
    directGather.use();
    shadowMap.bind(directGather);
    directGather.set("uFirstPixel", static_cast<unsigned>(first));
    directGather.set("uPixelCount", static_cast<unsigned>(count));
    gl::dispatchThreads(count, kWorkGroupSize);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    TOFSIM_GL_CHECK("direct gather");
    std::size_t done = s * (1 + batches) + 1;
    if (progress) progress(done, workUnits, "segment/VPL-batch passes");
    for (std::size_t b = 0; b < batches; ++b) {
      gbuffer.position.bindUnit(0);
      gbuffer.normal.bindUnit(1);
      gbuffer.albedo.bindUnit(2);
      indirectLight->gatherBatch(b, GatherTarget{first, count});
      if (progress) progress(++done, workUnits, "segment/VPL-batch passes");
    }

    directBuffer.download(0, floats * sizeof(float), direct.data());
    indirectBuffer.download(0, floats * sizeof(float), indirect.data());
    outsideBuffer.download(0, count * 2 * sizeof(float), outside.data());
    for (std::size_t i = 0; i < count; ++i) {
      result.offAxis.before += outside[2 * i];
      result.offAxis.after += outside[2 * i + 1];
    }
    result.offAxis += lightView.addTo(first, count, axis, kChannels, direct.data());

    Segment segment;
    segment.firstPixel = first;
    segment.pixelCount = count;
    segment.direct = direct.data();
    segment.indirect = indirect.data();
    sink.consume(segment);
  }
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace tofsim::render
