#include "tofsim/render/GlBackend.h"

#include <algorithm>

#include "GatherResponseClasses.h"
#include "GatherUniforms.h"
#include "GpuContract.h"
#include "GpuScene.h"
#include "IndirectLight.h"
#include "LightShadowMap.h"
#include "LightUniforms.h"
#include "MediumDirect.h"
#include "MediumVpls.h"
#include "MediumUniforms.h"
#include "PixelFootprint.h"
#include "RegionLegs.h"
#include "SampleBuffers.h"
#include "SurfaceMaps.h"
#include "Vpls.h"
#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Check.h"
#include "tofsim/gl/Compute.h"
#include "tofsim/gl/Context.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/ir/MediumVpl.h"
#include "tofsim/ir/RsmTexels.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/physics/FootprintKernel.h"
#include "tofsim/ir/VplClasses.h"
#include "tofsim/physics/TemporalResponse.h"
#include "tofsim/util/Error.h"

namespace tofsim::render {

using namespace capture;  // the job description types

// footprint_deposit.glsl writes the narrow bins and the slots as straight-line
// calls (llvmpipe's loop guard), one per bin and per slot.
static_assert(physics::FOOTPRINT_DIRECT_BINS == 16 && physics::FOOTPRINT_SLOTS == 12,
              "update the straight-line deposits of shaders/footprint_deposit.glsl");

namespace {

// Scene bounds grown to hold the viewpoint and the light, for depth ranges.
struct ViewBounds {
  explicit ViewBounds(const RenderJob& job) {
    const scene::Bounds b = job.scene->bounds();
    const glm::vec3 eye = viewpoint(job.imager);
    lo = glm::min(glm::min(b.min, eye), job.light.position_world);
    hi = glm::max(glm::max(b.max, eye), job.light.position_world);
  }
  glm::vec3 lo, hi;
};

}  // namespace

// The scene's GL objects, made once per scene (setScene): the geometry, and
// the triangle soup with its BVH the indirect gathers' visibility walks,
// built when a render first has VPLs.
struct GlBackend::SceneObjects {
  explicit SceneObjects(const scene::Scene& s) : scene(s), gpuScene(s) {}
  const scene::TriangleSoup& soup() {
    if (!triangleSoup)
      triangleSoup = std::make_unique<scene::TriangleSoup>(scene::buildTriangleSoup(scene));
    return *triangleSoup;
  }

  const scene::Scene& scene;
  GpuScene gpuScene;
  std::unique_ptr<scene::TriangleSoup> triangleSoup;
};

// One render's GL objects, in the order they are made.
struct GlBackend::Passes {
  Passes(const RenderJob& renderJob, const GpuScene& scene)
      : job(renderJob),
        bounds(job),
        gpuScene(scene),
        samplesPerSide(job.settings.pixel_samples),
        gbuffer(imageWidth(job.imager) * samplesPerSide, imageHeight(job.imager) * samplesPerSide,
                job.settings.materials == capture::MaterialModel::Gltf),
        shadowMap(job.settings.shadow_map_resolution, job.light.position_world, bounds.lo,
                  bounds.hi) {}

  std::size_t pixelCount() const {
    return static_cast<std::size_t>(imageWidth(job.imager)) * imageHeight(job.imager);
  }
  bool gltf() const { return job.settings.materials == capture::MaterialModel::Gltf; }

  // Appends a given image's vertices to the table (SurfaceMaps::load); a
  // hit sample of another model than the render's (a medium point) keeps
  // the gathers from folding the model (gpu::gatherDefines).
  std::size_t appendVertices(const ir::SurfaceImage& samples) {
    const std::size_t first = vertices.size();
    vertices.insert(vertices.end(), samples.vertex.begin(), samples.vertex.end());
    const int model = ir::vertexModelOf(job.settings.materials);
    for (std::size_t i = 0; i < samples.vertex.size(); ++i) {
      if (samples.position[i].w != 0.0f && samples.vertex[i].model != model) foldModel = false;
    }
    return first;
  }

  // The gathers' G-buffer: the samples', and with adaptive samples the
  // centres' and the mask that picks between them (surface_samples.glsl).
  void bindSurfaces() const {
    gbuffer.position.bindUnit(gpu::kGPosition);
    gbuffer.normal.bindUnit(gpu::kGNormal);
    gbuffer.albedo.bindUnit(gpu::kGAlbedo);
    vertexTable.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kScatterVertices);
    if (gltf()) gbuffer.metallicRoughness.bindUnit(gpu::kGMetallicRoughness);
    if (pixelRaySteps.size() > 0) {
      pixelRaySteps.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kPixelRaySteps);
    }
    if (sampleCameraEnds.size() > 0) {
      sampleCameraEnds.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kSampleCameraEnds);
    }
    responseClasses.bind();
    if (regionLegs) regionLegs->bind();
    if (!centres) return;
    centres->position.bindUnit(gpu::kCentrePosition);
    centres->normal.bindUnit(gpu::kCentreNormal);
    centres->albedo.bindUnit(gpu::kCentreAlbedo);
    if (gltf()) centres->metallicRoughness.bindUnit(gpu::kCentreMetallicRoughness);
    sampledPixels.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kSampledPixels);
  }

  RenderJob job;
  ViewBounds bounds;
  const GpuScene& gpuScene;  ///< the backend's (SceneObjects)
  int32_t samplesPerSide;    ///< render.pixel_samples
  SurfaceMaps gbuffer;       ///< the samples': (width N) x (height N), surface_samples.glsl
  /// The vertices the G-buffers' texels index while they are made: the
  /// scene's materials' (ir::materialVertices), then given samples'
  /// (appendVertices), uploaded to vertexTable by prepareSurfaces; and whether
  /// they all have the render's model (the gathers' SCATTER_MODEL).
  std::vector<physics::ScatterVertex> vertices;
  gl::Buffer vertexTable;
  bool foldModel = true;
  /// render.adaptive_pixel_samples (N > 1) only: the W x H pixel-centre
  /// G-buffer, the one sample of a masked-out pixel, and the mask, one uint
  /// per pixel (an SSBO indexed by the pixel index the gathers already hold;
  /// 4 bytes a pixel is small next to the N^2 x 64 of the G-buffer).
  std::unique_ptr<SurfaceMaps> centres;
  gl::Buffer sampledPixels;
  /// A lens camera with render.pixel_footprint only: each pixel's ray steps
  /// (PIXEL_RAY_STEPS in footprint_deposit.glsl), two vec4 a pixel.
  gl::Buffer pixelRaySteps;
  /// Given samples with their own camera ends only (SAMPLE_CAMERA_ENDS in
  /// camera_end.glsl): one vec4 per sample, then one per pixel centre.
  gl::Buffer sampleCameraEnds;
  GatherResponseClasses responseClasses;  ///< the gathers' (none without delays)
  LightShadowMap shadowMap;
  gl::Program directGather;
  std::unique_ptr<IndirectLight> indirectLight;  ///< null without VPLs
  std::unique_ptr<MediumDirect> mediumDirect;    ///< null without a scattering medium
  std::unique_ptr<MediumVpls> mediumVpls;  ///< null without VPLs and a scattering medium
  /// Per-region media (`media:`) only: the regions on the device and the
  /// samples' legs through them; on the host for the VPLs' light legs.
  std::unique_ptr<RegionLegs> regionLegs;
  capture::MediumRegions regions;
  gl::Buffer directVolume, indirectVolume;
  gl::Buffer outsideAxis;                     ///< per pixel: light before the axis, light after it
  std::unique_ptr<PixelFootprint> footprint;  ///< null without render.pixel_footprint
  std::size_t firstPixel = 0, segmentPixels = 0;
  std::vector<float> outside;
};

GlBackend::GlBackend(gl::Context& context) : context_(context) {}

GlBackend::GlBackend(std::unique_ptr<gl::Context> context)
    : ownedContext_(std::move(context)), context_(*ownedContext_) {}

GlBackend::~GlBackend() = default;

GlBackend::Passes& GlBackend::passes() const {
  TOFSIM_CHECK_MSG(passes_ != nullptr, "prepareSurfaces must come first");
  return *passes_;
}

std::string GlBackend::description() const { return context_.description(); }

ir::DeviceLimits GlBackend::limits() const {
  const gl::ContextLimits& gl = context_.limits();
  ir::DeviceLimits limits;
  limits.maxImageSide = gl.maxTextureSize;
  limits.maxBufferBytes = gl.maxShaderStorageBlockBytes;
  limits.maxPixelsPerPass =
      static_cast<std::size_t>(gl.maxComputeWorkGroupCount[0]) * gpu::kWorkGroupSize;
  return limits;
}

void GlBackend::setScene(const scene::Scene& scene, const rays::RayScene* /*rays*/) {
  passes_.reset();  // a render's objects refer to the scene's
  sceneObjects_.reset();
  sceneObjects_ = std::make_unique<SceneObjects>(scene);
}

void GlBackend::setSurfaces(std::unique_ptr<ir::SurfaceImage> samples,
                            std::unique_ptr<ir::SurfaceImage> centres) {
  TOFSIM_CHECK(samples != nullptr);
  givenSamples_ = std::move(samples);
  givenCentres_ = std::move(centres);
}

ir::CentreSurfaces GlBackend::prepareSurfaces(const RenderJob& job) {
  passes_.reset();  // the previous render's GL objects go first
  TOFSIM_CHECK_MSG(sceneObjects_ != nullptr && &sceneObjects_->scene == job.scene,
                   "setScene with the job's scene must come first");
  const int32_t n = job.settings.pixel_samples;
  const int32_t width = imageWidth(job.imager), height = imageHeight(job.imager);
  const int32_t maxSide = context_.limits().maxTextureSize;
  if (n > 1 && (width * n > maxSide || height * n > maxSide)) {
    throw InputError("camera.resolution " + std::to_string(width) + "x" + std::to_string(height) +
                     " times render.pixel_samples " + std::to_string(n) +
                     " exceeds the GL texture limit " + std::to_string(maxSide) +
                     " for the sub-pixel G-buffer");
  }
  passes_ = std::make_unique<Passes>(job, sceneObjects_->gpuScene);
  Passes& p = *passes_;
  p.vertices = ir::materialVertices(*job.scene, ir::vertexModelOf(job.settings.materials));
  ir::CentreSurfaces surfaces =
      pinhole(job.imager) != nullptr ? rasterizeSurfaces(p) : loadGivenSurfaces(p);
  // Never empty: a texel that saw nothing names entry 0.
  if (p.vertices.empty()) p.vertices.push_back(physics::ScatterVertex{});
  p.vertexTable = gl::Buffer(p.vertices.size() * sizeof(physics::ScatterVertex),
                             p.vertices.data(), 0);
  // The table lives on the device from here: given samples add one entry
  // each, so their host copy would otherwise stay for the whole render.
  p.vertices = {};
  if (const Camera* camera = cameraOf(job.imager);
      camera && camera->lens && job.settings.pixel_footprint) {
    p.pixelRaySteps = pixelRayStepsBuffer(*camera);
  }
  if (gpu::adaptiveSamples(job.settings)) {
    // Until setSampledPixels: every pixel takes its N x N samples.
    p.sampledPixels = gl::Buffer(p.pixelCount() * sizeof(uint32_t));
    p.sampledPixels.fill(1u);
  }
  p.shadowMap.render(p.gpuScene);

  p.responseClasses = GatherResponseClasses(responseClasses_);
  std::vector<std::pair<std::string, std::string>> defines = gpu::gatherDefines(job, p.foldModel);
  defines.insert(defines.end(), p.responseClasses.defines().begin(),
                 p.responseClasses.defines().end());
  p.directGather = gpu::makeProgram({{GL_COMPUTE_SHADER, "direct_gather.comp"}}, defines);
  setLightUniforms(p.directGather, job.light);
  p.shadowMap.bind(p.directGather);
  configureGather(p.directGather, job);
  // An absorbing medium scatters nothing into the rays (it only attenuates).
  if (job.settings.medium.scatters()) {
    p.mediumDirect = std::make_unique<MediumDirect>(job, p.foldModel);
  }
  // Per-region media: every sample's camera and light legs through the
  // regions, once, for the gathers.
  if (!job.settings.media.empty()) {
    p.regions = MediumRegions(job.settings.media, *job.scene, job.settings.time.index_of_refraction);
    p.regionLegs = std::make_unique<RegionLegs>(job, p.foldModel);
    p.bindSurfaces();
    p.regionLegs->compute();
  }
  return surfaces;
}

ir::CentreSurfaces GlBackend::rasterizeSurfaces(Passes& p) const {
  const Camera& camera = p.job.camera();
  const glm::vec2 range = depthRange(p.bounds.lo, p.bounds.hi, camera.position_world);
  const glm::mat4 viewProjection = camera.projection(range.x, range.y) * camera.view();
  p.gbuffer.render(p.gpuScene, viewProjection, camera.position_world);
  // The driver's G-buffer (depth, the light seen by the camera, the adaptive
  // samples' edges) is the pixel centres', whatever the sub-pixel samples:
  // with several, a W x H one, rasterized as pixel_samples: 1 rasterizes its
  // G-buffer, only for this download unless adaptive samples read it too.
  ir::CentreSurfaces surfaces;
  surfaces.positions.resize(p.pixelCount() * 4);
  surfaces.normals.resize(p.pixelCount() * 4);
  const auto download = [&](const SurfaceMaps& maps) {
    maps.position.download(GL_RGBA, GL_FLOAT, surfaces.positions.size() * sizeof(float),
                           surfaces.positions.data());
    maps.normal.download(GL_RGBA, GL_FLOAT, surfaces.normals.size() * sizeof(float),
                         surfaces.normals.data());
  };
  if (p.samplesPerSide == 1) {
    download(p.gbuffer);
    return surfaces;
  }
  const bool adaptive = gpu::adaptiveSamples(p.job.settings);
  auto centres = std::make_unique<SurfaceMaps>(camera.width, camera.height, adaptive && p.gltf());
  centres->render(p.gpuScene, viewProjection, camera.position_world);
  download(*centres);
  if (adaptive) p.centres = std::move(centres);
  return surfaces;
}

ir::CentreSurfaces GlBackend::loadGivenSurfaces(Passes& p) {
  TOFSIM_CHECK_MSG(givenSamples_ != nullptr,
                   "an imager that is not a pinhole needs setSurfaces before prepareSurfaces");
  const std::unique_ptr<ir::SurfaceImage> samples = std::move(givenSamples_);
  const std::unique_ptr<ir::SurfaceImage> centres = std::move(givenCentres_);
  p.gbuffer.load(*samples, p.samplesPerSide, p.appendVertices(*samples));
  const bool adaptive = gpu::adaptiveSamples(p.job.settings);
  if (!raysShareOrigin(p.job.imager)) {
    p.sampleCameraEnds = sampleCameraEndsBuffer(*samples, adaptive ? centres.get() : nullptr);
  }
  if (p.samplesPerSide == 1) return ir::centresOf(*samples);
  TOFSIM_CHECK_MSG(centres != nullptr, "setSurfaces needs the pixel centres' samples with N > 1");
  if (adaptive) {
    p.centres = std::make_unique<SurfaceMaps>(samples->width, samples->height, p.gltf());
    p.centres->load(*centres, 1, p.appendVertices(*centres));
  }
  return ir::centresOf(*centres);
}

void GlBackend::setSampledPixels(const std::vector<uint8_t>& sampled) {
  Passes& p = passes();
  TOFSIM_CHECK_MSG(p.centres != nullptr,
                   "setSampledPixels needs render.adaptive_pixel_samples with pixel_samples > 1");
  TOFSIM_CHECK_EQ(sampled.size(), p.pixelCount());
  // Widened to the shader's uint: an 8-bit SSBO element would need
  // GL_EXT_shader_8bit_storage, which GL 4.5 does not promise.
  const std::vector<uint32_t> words(sampled.begin(), sampled.end());
  p.sampledPixels.upload(0, words.size() * sizeof(uint32_t), words.data());
}

std::vector<ir::Vpl> GlBackend::generateVpls(const RenderJob& job) {
  const IndirectSettings& s = job.settings.indirect;
  if (!s.enabled) return {};
  const Passes& p = passes();
  std::vector<ir::Vpl> vpls = render::generateVpls(
      p.gpuScene, job.light, s.rsm_resolution, s.rsm_edge_samples,
      job.settings.time.index_of_refraction, p.bounds.lo, p.bounds.hi,
      ir::vertexModelOf(job.settings.materials), job.settings.medium);
  ir::setFirstBounceClasses(vpls, responseClasses_);
  // Per-region media: each VPL's light -> VPL leg (the CPU backend's call).
  ir::attenuateLightLegs(vpls, p.regions, job.light.position_world,
                         job.settings.time.index_of_refraction);
  return vpls;
}

void GlBackend::setVpls(const std::vector<ir::Vpl>& vpls) {
  Passes& p = passes();
  p.indirectLight.reset();
  if (vpls.empty()) return;
  // A medium VPL's vertex is not of the render's model: the gather reads
  // each VPL's (no SCATTER_MODEL folding).
  const bool foldModel = p.foldModel && std::none_of(vpls.begin(), vpls.end(), ir::isMediumVpl);
  p.indirectLight = std::make_unique<IndirectLight>(
      sceneObjects_->soup(), vpls, p.job, foldModel, p.responseClasses.defines());
  configureIndirectGather(p.indirectLight->gatherProgram(), p.job);
  if (p.regionLegs) p.regionLegs->setUniforms(p.indirectLight->gatherProgram());
  p.mediumVpls.reset();
  if (p.job.settings.vplsLightCameraRays()) {
    p.mediumVpls = std::make_unique<MediumVpls>(p.job, vpls, *p.mediumDirect);
  }
}

std::size_t GlBackend::fixedBytes() const {
  const Passes& p = passes();
  // The G-buffer: four RGBA32F-sized targets per sample, and an RG32F one
  // with render.materials: gltf; with adaptive samples as much again per
  // pixel for the centres' maps, and the mask's uint.
  auto samples = static_cast<std::size_t>(p.samplesPerSide) * p.samplesPerSide;
  if (p.centres) ++samples;
  const std::size_t floatsPerSample = 4 * 4 + (p.gltf() ? 2 : 0);
  std::size_t bytes = p.gpuScene.bytes() +
                      p.pixelCount() * samples * floatsPerSample * sizeof(float) +
                      p.shadowMap.bytes() + p.sampledPixels.size() + p.pixelRaySteps.size() +
                      p.vertexTable.size() + p.sampleCameraEnds.size() +
                      p.responseClasses.bytes();
  if (p.mediumDirect) bytes += p.mediumDirect->bytes();
  if (p.regionLegs) bytes += p.regionLegs->bytes();
  if (p.indirectLight) bytes += p.indirectLight->fixedBytes();
  return bytes;
}

std::size_t GlBackend::visibilityBytesPerVpl() const {
  const Passes& p = passes();
  return p.indirectLight ? p.indirectLight->ismBytesPerVpl() : 0;
}

void GlBackend::allocate(std::size_t pixelsPerSegment, std::size_t vplsPerBatch) {
  Passes& p = passes();
  if (p.indirectLight) p.indirectLight->allocate(vplsPerBatch);
  const std::size_t floats =
      pixelsPerSegment * static_cast<std::size_t>(p.job.settings.time.bins) * gpu::kChannels;
  p.directVolume = gl::Buffer(floats * sizeof(float));
  p.indirectVolume = gl::Buffer(floats * sizeof(float));
  p.outsideAxis = gl::Buffer(pixelsPerSegment * 2 * sizeof(float));
  p.outside.resize(pixelsPerSegment * 2);
  // The plan counted the difference buffer (capture::PixelBuffers::footprintBuffers).
  p.footprint.reset();
  if (p.job.settings.pixel_footprint || responseClasses_.delayed()) {
    const std::vector<std::vector<physics::ResponseTaps>> delayed =
        physics::classStages(responseClasses_, p.job.settings.time.bin_width_s);
    p.footprint =
        std::make_unique<PixelFootprint>(pixelsPerSegment, p.job.settings.time.bins, delayed);
  }
  // The gathers' depositDelayed: class c's pixels are region c of the buffer.
  if (p.responseClasses.delayed()) {
    p.responseClasses.setRegionPixels(p.directGather, p.footprint->regionPixels());
    if (p.indirectLight) {
      p.responseClasses.setRegionPixels(p.indirectLight->gatherProgram(),
                                        p.footprint->regionPixels());
    }
  }
}

void GlBackend::setResponseClasses(const physics::ResponseClassTable& classes) {
  // Read from prepareSurfaces on (the gathers' programs, the VPLs' classes,
  // allocate's stage): a render prepared before it is dropped, so that one
  // prepared with another table cannot run.
  passes_.reset();
  responseClasses_ = classes;
}

void GlBackend::buildVisibility(std::size_t firstVpl, std::size_t count) {
  Passes& p = passes();
  TOFSIM_CHECK(p.indirectLight != nullptr);
  p.indirectLight->buildVisibility(firstVpl, count);
}

void GlBackend::beginSegment(std::size_t firstPixel, std::size_t count) {
  Passes& p = passes();
  p.firstPixel = firstPixel;
  p.segmentPixels = count;
  const std::size_t bytes =
      count * static_cast<std::size_t>(p.job.settings.time.bins) * gpu::kChannels * sizeof(float);
  p.directVolume.clear();
  p.indirectVolume.clear();
  p.outsideAxis.clear();
  p.directVolume.bindRange(GL_SHADER_STORAGE_BUFFER, gpu::kDirectVolume, 0, bytes);
  p.indirectVolume.bindRange(GL_SHADER_STORAGE_BUFFER, gpu::kIndirectVolume, 0, bytes);
  p.outsideAxis.bindRange(GL_SHADER_STORAGE_BUFFER, gpu::kOutsideAxis, 0,
                          count * 2 * sizeof(float));
  if (p.footprint) p.footprint->beginSegment(count);
  if (p.mediumVpls) p.mediumVpls->beginSegment(count);
}

void GlBackend::gatherDirect() {
  Passes& p = passes();
  p.bindSurfaces();
  p.directGather.use();
  p.shadowMap.bind(p.directGather);
  p.directGather.set("uFirstPixel", static_cast<unsigned>(p.firstPixel));
  p.directGather.set("uPixelCount", static_cast<unsigned>(p.segmentPixels));
  gl::dispatchThreads(p.segmentPixels, gpu::kWorkGroupSize);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  // The wide kernels' buffer into the direct volume; it is then the indirect
  // gathers'.
  if (p.footprint) p.footprint->integrateInto(p.directVolume, p.segmentPixels);
  if (p.mediumDirect) p.mediumDirect->gather(p.shadowMap, p.firstPixel, p.segmentPixels);
  TOFSIM_GL_CHECK("direct gather");
}

void GlBackend::gatherIndirect(std::size_t firstVpl, std::size_t count) {
  Passes& p = passes();
  TOFSIM_CHECK(p.indirectLight != nullptr);
  p.bindSurfaces();
  p.indirectLight->gather(firstVpl, count, p.firstPixel, p.segmentPixels);
  if (p.mediumVpls) {
    p.mediumVpls->gather(*p.indirectLight, firstVpl, count, p.firstPixel, p.segmentPixels);
  }
}

void GlBackend::takeIndirect(float* indirect) {
  Passes& p = passes();
  // The integration zeroes the difference buffer behind it (footprint_integrate.comp).
  if (p.footprint) p.footprint->integrateInto(p.indirectVolume, p.segmentPixels);
  const std::size_t bytes = p.segmentPixels * static_cast<std::size_t>(p.job.settings.time.bins) *
                            gpu::kChannels * sizeof(float);
  p.indirectVolume.download(0, bytes, indirect);
  if (p.mediumVpls) p.mediumVpls->addInto(indirect, nullptr, p.segmentPixels);
  p.indirectVolume.clear();
  // The gathers write through the binding of beginSegment's range, which
  // clear() leaves in place; the barrier orders the clear before them.
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  TOFSIM_GL_CHECK("indirect read-back");
}

void GlBackend::readSegment(float* direct, float* indirect, AxisLoss& offAxis) {
  Passes& p = passes();
  // The indirect gathers' wide kernels, after every batch: one sum per pixel.
  if (p.footprint) p.footprint->integrateInto(p.indirectVolume, p.segmentPixels);
  const std::size_t bytes = p.segmentPixels * static_cast<std::size_t>(p.job.settings.time.bins) *
                            gpu::kChannels * sizeof(float);
  p.directVolume.download(0, bytes, direct);
  p.indirectVolume.download(0, bytes, indirect);
  p.outsideAxis.download(0, p.segmentPixels * 2 * sizeof(float), p.outside.data());
  if (p.mediumVpls) p.mediumVpls->addInto(indirect, p.outside.data(), p.segmentPixels);
  for (std::size_t i = 0; i < p.segmentPixels; ++i) {
    offAxis.before += p.outside[2 * i];
    offAxis.after += p.outside[2 * i + 1];
  }
}

}  // namespace tofsim::render
