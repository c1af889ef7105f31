#pragma once
// C++ face of shaders/vpl_near_field.glsl (a VPL's light near its own patch):
// the GLSL names it uses are GLM's, its functions inline functions of
// tofsim::physics, as TransientPhysics.h does for transient_physics.glsl.

#include <glm/glm.hpp>

#include "tofsim/physics/TransientPhysics.h"

namespace tofsim::physics {

using glm::abs;
using glm::cross;

#define TOFSIM_PHYSICS_FN inline
#include "vpl_near_field.glsl"
#undef TOFSIM_PHYSICS_FN

}  // namespace tofsim::physics
