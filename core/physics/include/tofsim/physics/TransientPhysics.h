#pragma once
// C++ face of shaders/transient_physics.glsl: the GLSL names it uses (vec3,
// min, floor) are GLM's, and its functions become inline functions of
// tofsim::physics. Compile with -ffp-contract=off where bytes must match the
// formula (a fused multiply-add rounds differently).

#include <glm/glm.hpp>

namespace tofsim::physics {

using glm::clamp;
using glm::dot;
using glm::floor;
using glm::ivec2;
using glm::length;
using glm::mat3;
using glm::max;
using glm::min;
using glm::sqrt;
using glm::transpose;
using glm::vec2;
using glm::vec3;

#define TOFSIM_PHYSICS_FN inline
#include "transient_physics.glsl"
#undef TOFSIM_PHYSICS_FN

}  // namespace tofsim::physics
