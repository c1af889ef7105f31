#pragma once
// The glTF metallic-roughness BRDF of issue 16 in double precision,
// transcribed from the issue independently of shaders/gltf_brdf.glsl: the
// closed forms of the glossy tests evaluate it for the light and view
// directions of each pixel.

#include <cmath>
#include <glm/glm.hpp>

namespace tofsim::test {

/// f(l, v) in 1/sr for unit normal n and unit l, v above the surface.
inline glm::dvec3 expectedGltfBrdf(const glm::dvec3& n, const glm::dvec3& l, const glm::dvec3& v,
                                   const glm::dvec3& base, double metallic, double roughness) {
  constexpr double kPi = 3.14159265358979323846;
  const double nl = glm::dot(n, l), nv = glm::dot(n, v);
  if (nl <= 0.0 || nv <= 0.0) return glm::dvec3(0.0);
  const glm::dvec3 h = glm::normalize(l + v);
  const double nh = glm::dot(n, h), vh = std::abs(glm::dot(v, h));
  const double a2 = std::pow(roughness, 4.0);
  const double d = a2 / (kPi * std::pow(nh * nh * (a2 - 1.0) + 1.0, 2.0));
  const double vis =
      0.5 / (nl * std::sqrt(nv * nv * (1.0 - a2) + a2) + nv * std::sqrt(nl * nl * (1.0 - a2) + a2));
  const auto fresnel = [&](const glm::dvec3& f0) {
    return f0 + (1.0 - f0) * std::pow(1.0 - vh, 5.0);
  };
  const glm::dvec3 f04 = fresnel(glm::dvec3(0.04));
  const glm::dvec3 dielectric = (1.0 - f04) * base / kPi + f04 * (d * vis);
  const glm::dvec3 metal = fresnel(base) * (d * vis);
  return (1.0 - metallic) * dielectric + metallic * metal;
}

}  // namespace tofsim::test
