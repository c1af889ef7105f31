#pragma once
// The GL backend's medium pass (issue 42, item 3): the light the medium
// filling the scene scatters once into each pixel sample's camera ray, per
// time bin (shaders/medium_direct.comp, by shaders/medium.glsl's
// quadrature), added to the segment's direct light after direct_gather.comp.
// Made only for a job whose medium is present: without one the GL backend
// runs what it ran before. The physics: core/physics/medium_single_scattering.md.

#include <cstddef>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Program.h"

namespace tofsim::render {

class LightShadowMap;

/// The uniforms every medium pass over the camera rays reads (time axis,
/// image, camera ends, samples' weight, the medium; medium_sample_rays.glsl).
void configureMediumPass(const gl::Program& program, const capture::RenderJob& job);

class MediumDirect {
 public:
  /// For `job` (its medium present) gathered from its G-buffer's samples
  /// (pixel_samples per side; the pixel centres too with adaptive samples);
  /// foldModel as the gathers' (gpu::gatherDefines).
  MediumDirect(const capture::RenderJob& job, bool foldModel);

  /// Adds the medium's light of the segment's pixels [firstPixel, + pixels)
  /// into the direct volume and the off-axis sums beginSegment bound, with
  /// the surfaces and the shadow map bound as for the direct gather.
  void gather(const LightShadowMap& shadowMap, std::size_t firstPixel, std::size_t pixels) const;

  /// Device memory it holds: the samples' ray directions.
  std::size_t bytes() const { return rays_.size(); }
  /// The samples' ray directions (medium_sample_rays.glsl's uMediumRays),
  /// which the VPLs' medium pass reads too (MediumVpls).
  const gl::Buffer& rays() const { return rays_; }

 private:
  gl::Program program_;
  gl::Buffer rays_;  ///< one vec4 direction per sample (medium_direct.comp)
};

}  // namespace tofsim::render
