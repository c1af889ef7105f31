#include "IndirectLight.h"

#include <algorithm>
#include <cstring>

#include "GpuContract.h"
#include "LoopGuard.h"
#include "tofsim/render/GlRegionLimits.h"
#include "tofsim/gl/Check.h"
#include "tofsim/gl/Compute.h"
#include "tofsim/ir/MediumVpl.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::render {

namespace {

// Loop trips one gather invocation may make per dispatch: llvmpipe silently
// ends every loop of an invocation after 65535 iterations in total (loop
// entries count too, so its count runs ahead of ours), so dispatches are sized
// to a third of that, with the shader's own guard (30000) as a check.
// Measured on the Cornell box: light went missing above ~45000 of our trips.
constexpr std::size_t kTripsPerDispatch = 20000;

std::vector<std::pair<std::string, std::string>> gatherDefines(
    const capture::RenderJob& job, bool foldModel,
    const std::vector<std::pair<std::string, std::string>>& responseDefines) {
  std::vector<std::pair<std::string, std::string>> defines = gpu::gatherDefines(job, foldModel);
  if (job.settings.indirect.visibility == capture::Visibility::Exact) {
    defines.emplace_back("EXACT_VISIBILITY", "1");
  }
  defines.insert(defines.end(), responseDefines.begin(), responseDefines.end());
  return defines;
}

void dispatchThreads(std::size_t threads) { gl::dispatchThreads(threads, gpu::kWorkGroupSize); }

// The VPL buffer as vpl.glsl declares it: whole VPLs where the gathers
// read their vertices (VPL_VERTICES: render.materials: gltf, a scattering
// medium), else each VPL's first kLambertianVplBytes (the Lambertian gathers
// read no material).
gl::Buffer vplBufferOf(const std::vector<ir::Vpl>& vpls, bool whole) {
  if (whole) return gl::Buffer(vpls.size() * sizeof(ir::Vpl), vpls.data(), 0);
  std::vector<unsigned char> packed(vpls.size() * ir::kLambertianVplBytes);
  for (std::size_t k = 0; k < vpls.size(); ++k) {
    std::memcpy(&packed[k * ir::kLambertianVplBytes], &vpls[k], ir::kLambertianVplBytes);
  }
  return gl::Buffer(packed.size(), packed.data(), 0);
}

}  // namespace

IndirectLight::IndirectLight(const TriangleSoup& soup, const std::vector<ir::Vpl>& vpls,
                             const capture::RenderJob& job, bool foldModel,
                             const std::vector<std::pair<std::string, std::string>>& responseDefines)
    : IndirectLight(soup, vpls, job.settings, gatherDefines(job, foldModel, responseDefines)) {
  // Per-region media: each VPL -> sample leg walks the regions' triangles
  // (medium_regions.glsl), whose regions the scene holds.
  if (!job.settings.media.empty()) {
    std::size_t triangles = 0;
    for (const scene::RegionMesh& r : job.scene->regions) triangles += r.triangles_world.size() / 3;
    regionTripsPerLeg_ = glRegionTripsPerLeg(job.scene->regions.size(), triangles);
  }
}

IndirectLight::IndirectLight(const TriangleSoup& soup, const std::vector<ir::Vpl>& vpls,
                             const capture::RenderSettings& settings,
                             const std::vector<std::pair<std::string, std::string>>& defines)
    : settings_(settings.indirect),
      seed_(settings.seed),
      samplesPerPixel_(static_cast<std::size_t>(settings.pixel_samples) * settings.pixel_samples),
      vplCount_(vpls.size()),
      triangleCount_(soup.triangleCount()),
      // A shadow ray visits about two nodes per level and a few leaves.
      tripsPerShadowRay_(std::min<std::size_t>(soup.bvh.size() + soup.triangleCount(),
                                               4 * static_cast<std::size_t>(soup.bvhDepth) + 16)),
      shadowRays_(settings.indirect.visibility == capture::Visibility::Exact ||
                  settings.medium.scatters()),
      gather_(gpu::makeProgram({{GL_COMPUTE_SHADER, "indirect_gather.comp"}}, defines)) {
  TOFSIM_CHECK(!vpls.empty() && triangleCount_ > 0);
  corners_ = gl::Buffer(soup.corners.size() * sizeof(glm::vec4), soup.corners.data(), 0);
  areaCdf_ = gl::Buffer(soup.areaCdf.size() * sizeof(float), soup.areaCdf.data(), 0);
  bvh_ = gl::Buffer(soup.bvh.size() * sizeof(BvhNode), soup.bvh.data(), 0);
  vplBuffer_ = vplBufferOf(vpls, ir::vplsCarryVertex(settings));
  loopGuard_ = gl::Buffer(sizeof(uint32_t));
  loopGuard_.clear();
  fixedBytes_ = corners_.size() + areaCdf_.size() + bvh_.size() + vplBuffer_.size();
  if (settings_.visibility == capture::Visibility::Ism) {
    // The splat reads the VPL buffer: the gather's struct Vpl.
    std::vector<std::pair<std::string, std::string>> vplLayout;
    if (ir::vplsCarryVertex(settings)) vplLayout.emplace_back("VPL_VERTICES", "1");
    splat_ = gpu::makeProgram({{GL_COMPUTE_SHADER, "ism_splat.comp"}}, vplLayout);
    pull_ = gpu::makeProgram({{GL_COMPUTE_SHADER, "ism_pull.comp"}});
    push_ = gpu::makeProgram({{GL_COMPUTE_SHADER, "ism_push.comp"}});
    for (int size = settings_.ism_resolution;; size = (size + 1) / 2) {
      levelOffsets_.push_back(floatsPerVpl_);
      levelSizes_.push_back(size);
      floatsPerVpl_ += static_cast<std::size_t>(size) * size;
      if (size == 1 || !settings_.ism_pull_push) break;
    }
  }
  // No uTriangleCount for the gather: only sampleSurface (the ISM splat)
  // reads it, so the compiler drops it from the exact variant.
}

std::size_t IndirectLight::ismBytesPerVpl() const { return floatsPerVpl_ * sizeof(float); }

void IndirectLight::allocate(std::size_t vplsPerBatch) {
  if (settings_.visibility == capture::Visibility::Ism) {
    ism_ = gl::Buffer(vplsPerBatch * ismBytesPerVpl());
  }
}

void IndirectLight::bindSceneBuffers() const {
  vplBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kVpls);
  corners_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kCorners);
  areaCdf_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kAreaCdf);
  bvh_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kBvh);
  if (ism_.id() != 0) ism_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kIsm);
  loopGuard_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kLoopGuard);
}

std::size_t IndirectLight::vplsPerDispatch() const {
  // Per VPL: its own trip, then per sample one trip of the sample loop (none
  // with one sample: no loop) and a shadow ray's; the footprint's deposits
  // are straight-line code (footprint_deposit.glsl) and cost none. With
  // adaptive samples a masked-out pixel loops over one sample, not N^2: the
  // N^2 pixels stay the worst case this counts. Per-region media add a leg's
  // passage through the regions per sample.
  const std::size_t shadowRay = shadowRays_ ? tripsPerShadowRay_ : 0;
  const std::size_t perSample = (samplesPerPixel_ > 1 ? 1 : 0) + shadowRay + regionTripsPerLeg_;
  const std::size_t tripsPerVpl = 1 + samplesPerPixel_ * perSample;
  return std::max<std::size_t>(1, kTripsPerDispatch / tripsPerVpl);
}

void IndirectLight::buildVisibility(std::size_t firstVpl, std::size_t count) {
  if (settings_.visibility != capture::Visibility::Ism) return;
  ismFirstVpl_ = firstVpl;
  ism_.fill(0x7f800000u);  // +inf: no surface seen in this direction
  bindSceneBuffers();
  const unsigned stride = static_cast<unsigned>(floatsPerVpl_);
  splat_.use();
  splat_.set("uFirstVpl", static_cast<unsigned>(firstVpl));
  splat_.set("uVplCount", static_cast<unsigned>(count));
  splat_.set("uPointsPerVpl", static_cast<unsigned>(capture::ismPointsPerVpl(settings_)));
  splat_.set("uVplStride", stride);
  splat_.set("uIsmResolution", settings_.ism_resolution);
  splat_.set("uSeed", static_cast<unsigned>(seed_ ^ (seed_ >> 32)));
  splat_.set("uTriangleCount", static_cast<unsigned>(triangleCount_));
  dispatchThreads(count * static_cast<std::size_t>(capture::ismPointsPerVpl(settings_)));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  const auto level = [&](const gl::Program& p, std::size_t fine, std::size_t threadsPerVpl) {
    p.use();
    p.set("uVplCount", static_cast<unsigned>(count));
    p.set("uVplStride", stride);
    p.set("uFineOffset", static_cast<unsigned>(levelOffsets_[fine]));
    p.set("uFineSize", levelSizes_[fine]);
    p.set("uCoarseOffset", static_cast<unsigned>(levelOffsets_[fine + 1]));
    p.set("uCoarseSize", levelSizes_[fine + 1]);
    dispatchThreads(count * threadsPerVpl);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  };
  for (std::size_t k = 0; k + 1 < levelSizes_.size(); ++k) {
    level(pull_, k, static_cast<std::size_t>(levelSizes_[k + 1]) * levelSizes_[k + 1]);
  }
  for (std::size_t k = levelSizes_.size() - 1; k-- > 0;) {
    level(push_, k, static_cast<std::size_t>(levelSizes_[k]) * levelSizes_[k]);
  }
  TOFSIM_GL_CHECK("ISM build");
}

void IndirectLight::bindVisibility(const gl::Program& program) const {
  bindSceneBuffers();
  program.use();
  if (settings_.visibility == capture::Visibility::Ism) {
    program.set("uVplStride", static_cast<unsigned>(floatsPerVpl_));
    program.set("uIsmResolution", settings_.ism_resolution);
    program.set("uIsmFirstVpl", static_cast<unsigned>(ismFirstVpl_));
  }
}

void IndirectLight::gather(std::size_t first, std::size_t count, std::size_t firstPixel,
                           std::size_t pixelCount) {
  bindVisibility(gather_);
  gather_.set("uFirstPixel", static_cast<unsigned>(firstPixel));
  gather_.set("uPixelCount", static_cast<unsigned>(pixelCount));
  // Sub-dispatches in VPL order keep each pixel's additions in index order.
  for (std::size_t done = 0; done < count;) {
    const std::size_t n = std::min(vplsPerDispatch(), count - done);
    gather_.set("uFirstVpl", static_cast<unsigned>(first + done));
    gather_.set("uVplCount", static_cast<unsigned>(n));
    dispatchThreads(pixelCount);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    done += n;
    throwIfInterrupted();  // Ctrl-C between dispatches, not only between segments
  }
  checkLoopGuard();
  TOFSIM_GL_CHECK("indirect gather");
}

void IndirectLight::checkLoopGuard() const {
  uint32_t loopLimitHit = 0;
  loopGuard_.download(0, sizeof loopLimitHit, &loopLimitHit);
  throwIfGuardRaised(loopLimitHit, "a gather invocation");
}

}  // namespace tofsim::render
