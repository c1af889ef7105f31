#pragma once
// Directions around a normal: an orthonormal basis and cosine-weighted
// hemisphere sampling, shared by the reference path tracer, IR's later-bounce
// VPLs and the glTF BRDF sampling (GltfSampling.h).

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace tofsim::physics {

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

}  // namespace tofsim::physics
