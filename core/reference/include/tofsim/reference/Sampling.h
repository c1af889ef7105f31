#pragma once
// Direction sampling for diffuse surfaces, and sub-pixel points.

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>

#include "tofsim/util/Random.h"

namespace tofsim::reference {

/// An orthonormal basis (t, b, n) around unit n without branches on a chosen
/// axis (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
inline void orthonormalBasis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float c = n.x * n.y * a;
  t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

/// Cosine-weighted direction on the hemisphere around unit n from two uniform
/// numbers in [0, 1): pdf = cos(theta) / pi (Malley's method).
inline glm::vec3 cosineSampleHemisphere(const glm::vec3& n, float u1, float u2) {
  constexpr float kTwoPi = 6.28318530717958647692f;
  const float r = std::sqrt(u1);
  const float phi = kTwoPi * u2;
  glm::vec3 t, b;
  orthonormalBasis(n, t, b);
  const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
  return glm::normalize(t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * z);
}

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

}  // namespace tofsim::reference
