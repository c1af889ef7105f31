#pragma once
// C++ face of shaders/random.glsl: the GPU's stateless hashes, bit for bit
// (uint is 32 bits in both languages, and wraps the same way).

#include <cstdint>

namespace tofsim::physics {

using uint = uint32_t;

#define TOFSIM_PHYSICS_FN inline
#include "random.glsl"
#undef TOFSIM_PHYSICS_FN

}  // namespace tofsim::physics
