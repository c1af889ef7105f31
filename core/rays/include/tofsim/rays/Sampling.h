#pragma once
// Direction sampling for diffuse surfaces (from core/physics), and sub-pixel points.

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>

#include "tofsim/physics/HemisphereSampling.h"
#include "tofsim/util/Random.h"

namespace tofsim::rays {

// The hemisphere sampling moved to core/physics (shared with the glTF BRDF
// sampling); the names stay here for the reference and IR's bounce VPLs.
using physics::cosineSampleHemisphere;
using physics::orthonormalBasis;

/// Sample `index` of `count` over a pixel, as an offset from its centre in
/// [-1/2, 1/2)^2 pixels: the first side^2 samples (side = floor(sqrt(count)))
/// take one cell each of a side x side grid, jittered inside it; the rest are
/// uniform over the pixel. Every cell is used once, so the mean is unbiased.
inline glm::vec2 stratifiedPixelOffset(int32_t index, int32_t count, Pcg32& rng) {
  int32_t side = 1;
  while ((side + 1) * (side + 1) <= count) ++side;
  const float jx = rng.nextFloat();
  const float jy = rng.nextFloat();
  if (index >= side * side) return {jx - 0.5f, jy - 0.5f};
  const float cell = 1.0f / static_cast<float>(side);
  return {(static_cast<float>(index % side) + jx) * cell - 0.5f,
          (static_cast<float>(index / side) + jy) * cell - 0.5f};
}

}  // namespace tofsim::rays
