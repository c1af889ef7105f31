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
/// render.indirect.vpl_brdf_clamp for a program that reads the VPLs'
/// vertices (VPL_VERTICES), where the compiled program still reads it: a
/// program folded on the Lambertian model (SCATTER_MODEL: no medium VPL
/// among the VPLs of a scattering medium's render) has every VPL's scatter
/// in its flux, and the compiler drops the uniform (a strict program would
/// refuse the name).
void setVplBrdfClamp(const gl::Program& program, const capture::RenderSettings& settings);

}  // namespace tofsim::render
