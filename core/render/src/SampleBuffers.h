#pragma once
// Storage buffers the gathers read beside the G-buffer, one entry per pixel
// or per sample, for imagers whose rays differ from pixel to pixel: a lens
// camera's ray steps (PIXEL_RAY_STEPS, footprint_deposit.glsl) and given
// samples' own camera ends (SAMPLE_CAMERA_ENDS, camera_end.glsl).

#include "tofsim/capture/Camera.h"
#include "tofsim/gl/Buffer.h"
#include "tofsim/ir/SurfaceImage.h"

namespace tofsim::render {

/// A lens camera's ray steps, pixel by pixel: two vec4 a pixel, the same
/// floats the CPU backend's PixelSteps takes.
gl::Buffer pixelRayStepsBuffer(const capture::Camera& camera);

/// The given samples' own camera ends (xyz) and lens paths (w), in the
/// samples' order, then the pixel centres' when `centres` is not null.
gl::Buffer sampleCameraEndsBuffer(const ir::SurfaceImage& samples,
                                  const ir::SurfaceImage* centres);

}  // namespace tofsim::render
