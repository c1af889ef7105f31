#pragma once
// C++ face of shaders/scatter_vertex.glsl (the scattering vertex and
// scatter()): the GLSL names it uses are GLM's, its functions inline
// functions of tofsim::physics. The vertex is a member of the std430 VPL
// record (shaders/vpl.glsl, ir::Vpl), so its C++ layout must be std430's.

#include <cstddef>
#include <glm/glm.hpp>

// The two files scatter_vertex.glsl includes, with the GLM names they use.
#include "tofsim/physics/GltfBrdf.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/physics/TransientPhysics.h"

namespace tofsim::physics {

using glm::vec4;

#define TOFSIM_PHYSICS_FN inline
#include "scatter_vertex.glsl"
#undef TOFSIM_PHYSICS_FN

// std430: a struct aligns to its largest member (vec4, 16 bytes), members at
// their natural offsets; glm's vec4 is four packed floats.
static_assert(sizeof(ScatterVertex) == 32);
static_assert(offsetof(ScatterVertex, color) == 0);
static_assert(offsetof(ScatterVertex, roughness) == 16);
static_assert(offsetof(ScatterVertex, model) == 20);
static_assert(offsetof(ScatterVertex, response) == 24);
static_assert(offsetof(ScatterVertex, responseParam) == 28);

}  // namespace tofsim::physics
