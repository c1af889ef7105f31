#pragma once
// The uniforms the GL gathers share (direct_gather.comp, indirect_gather.comp):
// image, time axis, imager, the medium; and the indirect gather's own.

#include "tofsim/capture/RenderJob.h"
#include "tofsim/gl/Program.h"

namespace tofsim::render {

/// Uniforms shared by the direct and indirect gathers.
void configureGather(const gl::Program& program, const capture::RenderJob& job);
/// The indirect gather's: configureGather's, the scene scale and the clamps.
void configureIndirectGather(const gl::Program& program, const capture::RenderJob& job);

}  // namespace tofsim::render
