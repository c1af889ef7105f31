#include "MediumDirect.h"

#include <vector>

#include "GpuContract.h"
#include "LightShadowMap.h"
#include "LightUniforms.h"
#include "MediumUniforms.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/gl/Check.h"
#include "tofsim/gl/Compute.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/util/Error.h"

namespace tofsim::render {

namespace {

// Every G-buffer sample's ray direction (ir::sampleRay, as the CPU backend
// traces them), in camera_end.glsl's layout: pixel p's N x N samples at
// p N^2 + s, then with adaptive samples each pixel centre's.
std::vector<glm::vec4> sampleDirections(const capture::Imager& imager, int32_t n, bool centres) {
  const capture::PrimaryRays rays(imager);
  const int32_t width = capture::imageWidth(imager), height = capture::imageHeight(imager);
  const std::size_t perPixel = static_cast<std::size_t>(n) * n;
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  std::vector<glm::vec4> directions;
  directions.reserve(pixels * perPixel + (centres ? pixels : 0));
  for (int32_t y = 0; y < height; ++y) {
    for (int32_t x = 0; x < width; ++x) {
      for (std::size_t s = 0; s < perPixel; ++s) {
        directions.emplace_back(ir::sampleRay(rays, nullptr, x, y, n, 1, s).ray.direction, 0.0f);
      }
    }
  }
  if (!centres) return directions;
  for (int32_t y = 0; y < height; ++y) {
    for (int32_t x = 0; x < width; ++x) {
      directions.emplace_back(ir::sampleRay(rays, nullptr, x, y, 1, 1, 0).ray.direction, 0.0f);
    }
  }
  return directions;
}

}  // namespace

void configureMediumPass(const gl::Program& p, const capture::RenderJob& job) {
  const capture::RenderSettings& s = job.settings;
  const bool adaptive = gpu::adaptiveSamples(s);
  const int32_t width = capture::imageWidth(job.imager);
  const auto pixels = static_cast<unsigned>(width * capture::imageHeight(job.imager));
  p.set("uImageWidth", width);
  p.set("uBins", s.time.bins);
  p.set("uStart_m", static_cast<float>(s.time.start_m()));
  p.set("uBinWidth_m", static_cast<float>(s.time.bin_width_m()));
  p.set("uIndexOfRefraction", static_cast<float>(s.time.index_of_refraction));
  // The CPU backend's dropLastLeg_: unwarped, or a last leg that takes no time.
  const bool dropLastLeg = s.time.camera_unwarp || !capture::lastLegCounts(job.imager);
  p.set("uCameraUnwarp", dropLastLeg ? 1 : 0);
  if (capture::raysShareOrigin(job.imager)) {
    p.set("uCameraPosition_world", capture::viewpoint(job.imager));
  } else if (adaptive) {
    p.set("uImagePixels", pixels);
  }
  if (adaptive) p.set("uMediumImagePixels", pixels);
  if (s.pixel_samples > 1) {
    p.set("uSampleWeight", 1.0f / static_cast<float>(s.pixel_samples * s.pixel_samples));
  }
  setMediumExtinction(p, s.medium);
  setMediumScattering(p, s.medium);
}

MediumDirect::MediumDirect(const capture::RenderJob& job, bool foldModel) {
  const capture::RenderSettings& s = job.settings;
  TOFSIM_CHECK(s.medium.present());
  // The G-buffer's layout and the sample's camera ends, as the gathers read them.
  program_ = gpu::makeProgram({{GL_COMPUTE_SHADER, "medium_direct.comp"}},
                              gpu::gatherDefines(job, foldModel));
  const std::vector<glm::vec4> directions =
      sampleDirections(job.imager, s.pixel_samples, gpu::adaptiveSamples(s));
  rays_ = gl::Buffer(directions.size() * sizeof(glm::vec4), directions.data());
  setLightUniforms(program_, job.light);
  configureMediumPass(program_, job);
}

void MediumDirect::gather(const LightShadowMap& shadowMap, std::size_t firstPixel,
                          std::size_t pixels) const {
  program_.use();
  shadowMap.bind(program_);
  rays_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kMediumRays);
  program_.set("uFirstPixel", static_cast<unsigned>(firstPixel));
  program_.set("uPixelCount", static_cast<unsigned>(pixels));
  gl::dispatchThreads(pixels, gpu::kWorkGroupSize);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  TOFSIM_GL_CHECK("medium direct light");
}

}  // namespace tofsim::render
