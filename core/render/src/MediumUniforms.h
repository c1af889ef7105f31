#pragma once
// Sets the uniforms of the medium filling the scene declared in
// shaders/medium_uniforms.glsl (a program compiled with MEDIUM:
// gpu::gatherDefines). Each setter sets only what its passes read, so a
// strict program (gl::Program::setStrictUniforms) finds every name.

#include "tofsim/capture/Medium.h"
#include "tofsim/gl/Program.h"

namespace tofsim::render {

/// uMediumSigmaT: what every attenuated leg needs (the gathers).
void setMediumExtinction(const gl::Program& program, const capture::Medium& medium);

/// uMediumSigmaS, uMediumPhase, uMediumG: what scattering in the medium needs.
void setMediumScattering(const gl::Program& program, const capture::Medium& medium);

}  // namespace tofsim::render
