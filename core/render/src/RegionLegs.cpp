#include "RegionLegs.h"

#include <algorithm>
#include <string>
#include <vector>

#include "GpuContract.h"
#include "LoopGuard.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/capture/MediumRegions.h"
#include "tofsim/gl/Check.h"
#include "tofsim/gl/Compute.h"
#include "tofsim/render/GlRegionLimits.h"
#include "tofsim/scene/RegionMeshes.h"
#include "tofsim/util/Error.h"

namespace tofsim::render {

namespace {

// struct Region of medium_regions.glsl (std430: four 16-byte members).
struct RegionRecord {
  glm::vec4 lo;  ///< w: the extra path per metre inside
  glm::vec4 hi;
  glm::vec4 sigmaT;
  glm::uvec4 triangles;  ///< x: first triangle, y: count
};
static_assert(sizeof(RegionRecord) == 64, "medium_regions.glsl's struct Region");

}  // namespace

RegionLegs::RegionLegs(const capture::RenderJob& job, bool foldModel) {
  const capture::RenderSettings& s = job.settings;
  TOFSIM_CHECK(!s.media.empty() && job.scene != nullptr);
  // The media's numbers as the CPU backend takes them (delayPerMetre, sigma_t).
  const capture::MediumRegions media(s.media, *job.scene, s.time.index_of_refraction);
  std::vector<RegionRecord> records;
  std::vector<glm::vec4> corners;
  const std::size_t limit = glRegionTriangleLimit(s.pixel_samples);
  for (std::size_t r = 0; r < s.media.size(); ++r) {
    const std::string& name = s.media[r].region;
    const auto mesh = std::find_if(job.scene->regions.begin(), job.scene->regions.end(),
                                   [&](const scene::RegionMesh& m) { return m.name == name; });
    TOFSIM_CHECK(mesh != job.scene->regions.end());  // as MediumRegions'
    RegionRecord record{};
    const scene::Bounds box = scene::regionBounds(*mesh);
    record.lo = glm::vec4(box.min, static_cast<float>(media.delayPerMetre(static_cast<int32_t>(r))));
    record.hi = glm::vec4(box.max, 0.0f);
    record.sigmaT = glm::vec4(s.media[r].medium.sigmaT(), 0.0f);
    record.triangles = glm::uvec4(static_cast<uint32_t>(corners.size() / 3),
                                  static_cast<uint32_t>(mesh->triangles_world.size() / 3), 0, 0);
    for (const glm::vec3& p : mesh->triangles_world) corners.emplace_back(p, 1.0f);
    records.push_back(record);
    if (corners.size() / 3 > limit) {
      throw InputError("the media's regions have " + std::to_string(corners.size() / 3) +
                       " triangles with the region '" + name + "': the GL backend takes at most " +
                       std::to_string(limit) + " with render.pixel_samples " +
                       std::to_string(s.pixel_samples) +
                       " (each leg walks them all; llvmpipe ends a shader's loops after 65535 "
                       "trips): use render.backend: cpu, fewer pixel samples, or a simpler mesh");
    }
  }
  regions_ = records.size();
  triangles_ = corners.size() / 3;
  regionBuffer_ = gl::Buffer(records.size() * sizeof(RegionRecord), records.data(), 0);
  corners_ = gl::Buffer(corners.size() * sizeof(glm::vec4), corners.data(), 0);
  const std::size_t pixels = static_cast<std::size_t>(capture::imageWidth(job.imager)) *
                             capture::imageHeight(job.imager);
  records_ = pixels * static_cast<std::size_t>(s.pixel_samples) * s.pixel_samples +
             (gpu::adaptiveSamples(s) ? pixels : 0);
  legs_ = gl::Buffer(records_ * 2 * sizeof(glm::vec4));
  guard_ = gl::Buffer(sizeof(uint32_t));
  guard_.clear();
  program_ = gpu::makeProgram({{GL_COMPUTE_SHADER, "region_legs.comp"}},
                              gpu::gatherDefines(job, foldModel));
  program_.use();
  program_.set("uRecordCount", static_cast<unsigned>(records_));
  program_.set("uImageWidth", capture::imageWidth(job.imager));
  program_.set("uImagePixels", static_cast<unsigned>(pixels));
  program_.set("uLightPosition_world", job.light.position_world);
  if (capture::raysShareOrigin(job.imager)) {
    program_.set("uCameraPosition_world", capture::viewpoint(job.imager));
  }
  setUniforms(program_);
}

void RegionLegs::setUniforms(const gl::Program& program) const {
  program.use();
  program.set("uRegionCount", static_cast<unsigned>(regions_));
}

void RegionLegs::bind() const {
  regionBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kRegions);
  corners_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kRegionCorners);
  legs_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kRegionLegs);
}

void RegionLegs::compute() const {
  bind();
  guard_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kLoopGuard);
  program_.use();
  gl::dispatchThreads(records_, gpu::kWorkGroupSize);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  uint32_t flags = 0;
  guard_.download(0, sizeof flags, &flags);
  throwIfGuardRaised(flags, "an invocation of the samples' legs through the media's regions");
  TOFSIM_GL_CHECK("region legs");
}

}  // namespace tofsim::render
