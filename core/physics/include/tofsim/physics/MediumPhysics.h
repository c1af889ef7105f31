#pragma once
// C++ face of shaders/medium.glsl (a homogeneous medium's phase functions and
// transmittance): its functions become inline functions of tofsim::physics,
// the GLSL names it uses GLM's.

#include <glm/glm.hpp>

#include "tofsim/physics/TransientPhysics.h"

namespace tofsim::physics {

using glm::abs;
using glm::atan;
using glm::ceil;
using glm::cos;
using glm::exp;
using glm::pow;
using glm::sin;
using glm::tan;

#define TOFSIM_PHYSICS_FN inline
#include "medium.glsl"
#undef TOFSIM_PHYSICS_FN

}  // namespace tofsim::physics
