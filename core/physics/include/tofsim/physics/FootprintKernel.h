#pragma once
// C++ face of shaders/footprint_kernel.glsl (the pixel footprint in time): the
// GLSL names it uses (vec3, dot, floor...) are GLM's, and its functions become
// inline functions of tofsim::physics. The deposit into a difference buffer
// and the per-pixel integration pass that use them are in FootprintBuffer.h.

#include <glm/glm.hpp>

namespace tofsim::physics {

using glm::abs;
using glm::clamp;
using glm::dot;
using glm::floor;
using glm::ivec2;
using glm::length;
using glm::max;
using glm::min;
using glm::sqrt;
using glm::vec2;
using glm::vec3;
using glm::vec4;

#define TOFSIM_PHYSICS_FN inline
#include "footprint_kernel.glsl"
#undef TOFSIM_PHYSICS_FN

}  // namespace tofsim::physics
