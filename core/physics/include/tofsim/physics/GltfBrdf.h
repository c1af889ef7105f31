#pragma once
// C++ face of shaders/gltf_brdf.glsl (the glTF metallic-roughness BRDF): the
// GLSL names it uses (vec3, dot, normalize...) are GLM's, and its functions
// become inline functions of tofsim::physics.

#include <glm/glm.hpp>

namespace tofsim::physics {

using glm::abs;
using glm::dot;
using glm::max;
using glm::min;
using glm::normalize;
using glm::sqrt;
using glm::vec3;

#define TOFSIM_PHYSICS_FN inline
#include "gltf_brdf.glsl"
#undef TOFSIM_PHYSICS_FN

}  // namespace tofsim::physics
