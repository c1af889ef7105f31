#include "SampleBuffers.h"

#include <vector>

#include "tofsim/util/Error.h"

namespace tofsim::render {

using capture::Camera;

// A lens camera's ray steps, pixel by pixel (PIXEL_RAY_STEPS): the same
// floats the CPU backend's PixelSteps takes.
gl::Buffer pixelRayStepsBuffer(const Camera& camera) {
  std::vector<glm::vec4> steps;
  steps.reserve(static_cast<std::size_t>(camera.width) * camera.height * 2);
  for (int32_t y = 0; y < camera.height; ++y) {
    for (int32_t x = 0; x < camera.width; ++x) {
      const Camera::RaySteps s = camera.rayStepsAt(x, y);
      steps.emplace_back(s.alongX, 0.0f);
      steps.emplace_back(s.alongY, 0.0f);
    }
  }
  return gl::Buffer(steps.size() * sizeof(glm::vec4), steps.data());
}

// The given samples' own camera ends (xyz) and lens paths (w), in the
// samples' order, then the pixel centres' (camera_end.glsl).
gl::Buffer sampleCameraEndsBuffer(const ir::SurfaceImage& samples, const ir::SurfaceImage* centres) {
  TOFSIM_CHECK_MSG(samples.aperture.size() == samples.size(),
                   "rays with their own origins need each sample's camera end");
  std::vector<glm::vec4> ends = samples.aperture;
  if (centres != nullptr) {
    TOFSIM_CHECK(centres->aperture.size() == centres->size());
    ends.insert(ends.end(), centres->aperture.begin(), centres->aperture.end());
  }
  return gl::Buffer(ends.size() * sizeof(glm::vec4), ends.data());
}

}  // namespace tofsim::render
