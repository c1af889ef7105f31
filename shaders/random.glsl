// Stateless hashing for reproducible random numbers on the GPU: the same
// (seed, indices) give the same numbers whatever the thread schedule. C++
// compiles it too (tofsim/physics/ShaderRandom.h), so the CPU backend draws
// the same ISM points.
#ifndef TOFSIM_RANDOM_GLSL
#define TOFSIM_RANDOM_GLSL

#ifndef TOFSIM_PHYSICS_FN
#define TOFSIM_PHYSICS_FN
#endif

TOFSIM_PHYSICS_FN uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

TOFSIM_PHYSICS_FN uint hash3(uint a, uint b, uint c) { return pcgHash(a ^ pcgHash(b ^ pcgHash(c))); }

// Uniform in [0, 1) with 24 bits.
TOFSIM_PHYSICS_FN float unitFloat(uint bits) { return float(bits >> 8u) * (1.0f / 16777216.0f); }

#endif
