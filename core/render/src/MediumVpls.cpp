#include "MediumVpls.h"

#include <algorithm>
#include <vector>

#include "GatherUniforms.h"
#include "GpuContract.h"
#include "IndirectLight.h"
#include "MediumDirect.h"
#include "tofsim/gl/Check.h"
#include "tofsim/gl/Compute.h"
#include "tofsim/ir/MediumRayVpls.h"
#include "tofsim/ir/MediumVpl.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::render {

namespace {

/// VPLs a dispatch: most of a ray's pairs are left by the roulette, and a
/// kept one is a few nodes; the shader's guard checks the loop trips.
constexpr std::size_t kVplsPerDispatch = 16;

}  // namespace

MediumVpls::MediumVpls(const capture::RenderJob& job, const std::vector<ir::Vpl>& vpls,
                       const MediumDirect& direct)
    : direct_(direct),
      floatsPerPixel_(static_cast<std::size_t>(job.settings.time.bins) * gpu::kChannels) {
  const capture::RenderSettings& s = job.settings;
  // Not folded on the render's model (SCATTER_MODEL): a medium VPL's vertex
  // is the medium's whatever the surfaces' model.
  std::vector<std::pair<std::string, std::string>> defines = gpu::gatherDefines(job, false);
  if (s.indirect.visibility == capture::Visibility::Exact) {
    defines.emplace_back("EXACT_VISIBILITY", "1");
  }
  program_ = gpu::makeProgram({{GL_COMPUTE_SHADER, "medium_vpls.comp"}}, defines);
  configureMediumPass(program_, job);
  const glm::vec3 extent = job.scene->bounds().max - job.scene->bounds().min;
  const float sceneScale_m = std::max(glm::length(extent), 1e-6f);
  program_.set("uSceneScale_m", sceneScale_m);  // as the gather's
  program_.set("uMediumRayThreshold", ir::mediumRayThreshold(vpls, sceneScale_m));
  program_.set("uMediumRaySeed", ir::mediumRaySeed(s.seed));
  program_.set("uVplRadius", physics::mediumVplRadius(
                                 static_cast<float>(s.indirect.geometry_term_clamp_per_m2)));
  setVplBrdfClamp(program_, s);
}

void MediumVpls::beginSegment(std::size_t pixels) {
  if (outside_.size() < pixels * 2 * sizeof(float)) {
    volume_ = gl::Buffer(pixels * floatsPerPixel_ * sizeof(float));
    outside_ = gl::Buffer(pixels * 2 * sizeof(float));
  }
  volume_.clear();
  outside_.clear();
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

void MediumVpls::gather(const IndirectLight& vpls, std::size_t firstVpl, std::size_t count,
                        std::size_t firstPixel, std::size_t pixels) const {
  vpls.bindVisibility(program_);
  direct_.rays().bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kMediumRays);
  volume_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kMediumVplVolume);
  outside_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kMediumVplOutside);
  program_.set("uFirstPixel", static_cast<unsigned>(firstPixel));
  program_.set("uPixelCount", static_cast<unsigned>(pixels));
  for (std::size_t k = firstVpl; k < firstVpl + count; k += kVplsPerDispatch) {
    program_.set("uFirstVpl", static_cast<unsigned>(k));
    program_.set("uVplCount",
                 static_cast<unsigned>(std::min(kVplsPerDispatch, firstVpl + count - k)));
    gl::dispatchThreads(pixels, gpu::kWorkGroupSize);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    throwIfInterrupted();
  }
  vpls.checkLoopGuard();
  TOFSIM_GL_CHECK("medium VPL light");
}

void MediumVpls::addInto(float* indirect, float* outside, std::size_t pixels) {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> light(pixels * floatsPerPixel_);
  volume_.download(0, light.size() * sizeof(float), light.data());
  for (std::size_t j = 0; j < light.size(); ++j) indirect[j] += light[j];
  if (outside != nullptr) {
    std::vector<float> lost(pixels * 2);
    outside_.download(0, lost.size() * sizeof(float), lost.data());
    for (std::size_t j = 0; j < lost.size(); ++j) outside[j] += lost[j];
    outside_.clear();
  }
  volume_.clear();
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace tofsim::render
