// The GL gathers' shared uniforms (GatherUniforms.h), moved out of
// GlBackend.cpp.
#include "GatherUniforms.h"

#include <algorithm>

#include "GpuContract.h"
#include "MediumUniforms.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/ir/MediumVpl.h"

namespace tofsim::render {

using namespace capture;  // the job description types

// Uniforms shared by the direct and indirect gathers: image, time axis,
// imager (its viewpoint, whether its last leg counts, its footprint steps),
// the medium (per-region media's regions: RegionLegs::setUniforms).
void configureGather(const gl::Program& program, const RenderJob& job) {
  const TimeAxis& axis = job.settings.time;
  program.set("uImageWidth", imageWidth(job.imager));
  program.set("uBins", axis.bins);
  program.set("uStart_m", static_cast<float>(axis.start_m()));
  program.set("uBinWidth_m", static_cast<float>(axis.bin_width_m()));
  program.set("uIndexOfRefraction", static_cast<float>(job.settings.time.index_of_refraction));
  // The CPU backend's dropLastLeg_: unwarped, or a last leg that takes no time.
  const bool dropLastLeg = job.settings.time.camera_unwarp || !lastLegCounts(job.imager);
  program.set("uCameraUnwarp", dropLastLeg ? 1 : 0);
  const RenderSettings& s = job.settings;
  if (s.medium.present()) setMediumExtinction(program, s.medium);  // compiled with MEDIUM
  // Each sample's own camera end, or the viewpoint for all (camera_end.glsl).
  // Where the centre samples' records start: their camera ends' and their
  // legs through per-region media's (surface_samples.glsl's sampleRecordIndex).
  if (raysShareOrigin(job.imager)) program.set("uCameraPosition_world", viewpoint(job.imager));
  if (gpu::adaptiveSamples(s) && (!raysShareOrigin(job.imager) || !s.media.empty())) {
    program.set("uImagePixels", static_cast<unsigned>(imageWidth(job.imager) * imageHeight(job.imager)));
  }
  const int32_t n = s.pixel_samples;
  // Each sample stands for 1 / N^2 of the pixel (as the CPU backend weighs it).
  if (s.pixel_footprint || n > 1) program.set("uSampleWeight", 1.0f / static_cast<float>(n * n));
  if (s.pixel_footprint) {
    const Camera* camera = cameraOf(job.imager);
    if (camera != nullptr) program.set("uCameraForward", camera->forward());
    // A lens's steps are each pixel's, in a buffer (Passes::pixelRaySteps).
    if (camera != nullptr && camera->lens) return;
    // A sample's footprint is its sub-pixel: the steps shrink by N.
    const PixelSteps sample(job.imager, 1.0f / static_cast<float>(n));
    program.set("uSampleStepX", sample.stepU());
    program.set("uSampleStepY", sample.stepV());
    // A masked-out pixel's one centre sample spans the whole pixel: the
    // steps of pixel_samples: 1 (whose side is 1), unscaled.
    if (gpu::adaptiveSamples(s)) {
      const PixelSteps pixel(job.imager, 1.0f);
      program.set("uPixelStepX", pixel.stepU());
      program.set("uPixelStepY", pixel.stepV());
    }
  }
}

// Uniforms of the indirect gather only: scene scale (biases) and the clamp.
void configureIndirectGather(const gl::Program& program, const RenderJob& job) {
  configureGather(program, job);
  const glm::vec3 extent = job.scene->bounds().max - job.scene->bounds().min;
  program.set("uSceneScale_m", std::max(glm::length(extent), 1e-6f));
  program.set("uGeometryClamp",
              static_cast<float>(job.settings.indirect.geometry_term_clamp_per_m2));
  setVplBrdfClamp(program, job.settings);
}

void setVplBrdfClamp(const gl::Program& program, const capture::RenderSettings& settings) {
  if (ir::vplsCarryVertex(settings) && glGetUniformLocation(program.id(), "uVplBrdfClamp") >= 0) {
    program.set("uVplBrdfClamp", static_cast<float>(settings.indirect.vpl_brdf_clamp_per_sr));
  }
}

}  // namespace tofsim::render
