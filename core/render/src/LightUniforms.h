#pragma once
// Sets the light's uniforms declared in shaders/light.glsl.

#include "tofsim/gl/Program.h"
#include "tofsim/capture/Light.h"

namespace tofsim::render {

using capture::Light;

void setLightUniforms(const gl::Program& program, const Light& light);

}  // namespace tofsim::render
