#pragma once
// Importance sampling of the glTF BRDF (GltfBrdf.h, shaders/gltf_brdf.glsl):
// a one-sample mixture of cosine-weighted directions (the diffuse lobe) and
// GGX visible-normal sampling (Heitz 2018, "Sampling the GGX Distribution of
// Visible Normals", JCGT 7(4), for the pinned alpha = roughness^2), weighted
// by the mixture's pdf: the balance heuristic of one-sample multiple
// importance sampling (Veach 1997, sec. 9.2.4). The reference path tracer's
// continuation and IR's later-bounce VPLs draw their directions here.
//
// Reciprocity: the BRDF is symmetric, so "v" may be the direction towards the
// viewer (a camera path) or towards where the light came from (a light path);
// the sampled direction is then the other one.
//
// Float limit: below roughness ~0.02, alpha^2 is under float's epsilon near 1,
// and D at a half vector that rounds to n overflows; such a sample's weight is
// returned as 0 (the path ends), so near-mirrors lose that part of their
// indirect light instead of making inf or NaN.

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "tofsim/physics/GltfBrdf.h"
#include "tofsim/physics/HemisphereSampling.h"

namespace tofsim::physics {

/// alpha = roughness^2 with gltfBrdf's clamp (kGltfMinRoughness).
inline float gltfAlpha(float roughness) {
  const float r = std::max(roughness, kGltfMinRoughness);
  return r * r;
}

/// Smith's masking function of GGX for a direction at cos theta = cosW > 0
/// from the normal: G1 = 2 cos / (cos + sqrt(alpha^2 + (1 - alpha^2) cos^2)).
inline float ggxSmithG1(float cosW, float alpha2) {
  if (cosW <= 0.0f) return 0.0f;
  return 2.0f * cosW / (cosW + std::sqrt(alpha2 + (1.0f - alpha2) * cosW * cosW));
}

/// A GGX microfacet normal drawn from the distribution of normals visible from
/// vLocal (unit, z > 0), in the frame where the surface normal is +z, from two
/// uniform numbers in [0, 1): Heitz 2018, listing 1, isotropic alpha.
inline glm::vec3 sampleGgxVisibleNormal(const glm::vec3& vLocal, float alpha, float u1, float u2) {
  constexpr float kTwoPi = 6.28318530717958647692f;
  // The view in the hemisphere configuration (the ellipsoid stretched to a sphere).
  const glm::vec3 vh = glm::normalize(glm::vec3(alpha * vLocal.x, alpha * vLocal.y, vLocal.z));
  const float lensq = vh.x * vh.x + vh.y * vh.y;
  const glm::vec3 t1 =
      lensq > 0.0f ? glm::vec3(-vh.y, vh.x, 0.0f) / std::sqrt(lensq) : glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 t2 = glm::cross(vh, t1);
  // A point on the projected area: a disk, its far half squashed by vh.z.
  const float r = std::sqrt(u1);
  const float phi = kTwoPi * u2;
  const float p1 = r * std::cos(phi);
  const float s = 0.5f * (1.0f + vh.z);
  const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
  const glm::vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
  // Back to the ellipsoid configuration.
  return glm::normalize(glm::vec3(alpha * nh.x, alpha * nh.y, std::max(0.0f, nh.z)));
}

/// Density (1/sr) of l = reflect(-v, h) for h drawn by sampleGgxVisibleNormal:
/// D_v(h) / (4 v.h) = G1(v) D(h) / (4 n.v), with h = normalize(l + v). Defined
/// on the whole sphere of l (reflections below the surface carry the mass that
/// the surface does not reflect), 0 where h is not a visible normal.
inline float ggxVisibleReflectionPdf(const glm::vec3& n, const glm::vec3& v, const glm::vec3& l,
                                     float alpha2) {
  const float nDotV = glm::dot(n, v);
  if (nDotV <= 0.0f || glm::dot(l + v, l + v) <= 0.0f) return 0.0f;
  // h and n.h exactly as gltfBrdf computes them, so that D here and in f are
  // the same float and cancel in f cos / pdf (a metal's weight F G2 / G1 <= 1
  // even where float D is off by a percent, below roughness ~0.1).
  const glm::vec3 h = glm::normalize(l + v);
  const float nDotH = glm::max(glm::dot(n, h), 0.0f);
  if (nDotH <= 0.0f || glm::dot(v, h) <= 0.0f) return 0.0f;
  return ggxSmithG1(nDotV, alpha2) * gltfGgxD(nDotH, alpha2) / (4.0f * nDotV);
}

/// Probability of drawing from the GGX lobe rather than the cosine lobe: the
/// lobes' shares of the BRDF's reflectance estimated at the view, with
/// Schlick's Fresnel at n.v and channel means,
///   specular = (1 - metallic) F(0.04, n.v) + metallic mean(F(baseColor, n.v)),
///   diffuse  = (1 - metallic) (1 - F(0.04, n.v)) mean(baseColor),
/// p = specular / (specular + diffuse) (1 for a metal, 0.5 for a black one at
/// normal view, where both are 0). Any p in (0, 1] keeps the estimator
/// unbiased: the visible-normal density is positive on the whole hemisphere.
inline float gltfSpecularLobeProbability(float nDotV, const glm::vec3& baseColor, float metallic) {
  const float cosV = std::clamp(nDotV, 0.0f, 1.0f);
  const float fDielectric = gltfSchlickF(vec3(kGltfDielectricF0), cosV).x;
  const glm::vec3 fMetal = gltfSchlickF(baseColor, cosV);
  const float specular =
      (1.0f - metallic) * fDielectric + metallic * (fMetal.x + fMetal.y + fMetal.z) / 3.0f;
  const float diffuse =
      (1.0f - metallic) * (1.0f - fDielectric) * (baseColor.x + baseColor.y + baseColor.z) / 3.0f;
  const float total = specular + diffuse;
  return total > 0.0f ? specular / total : 0.5f;
}

/// The mixture's density (1/sr) of direction l seen from v (unit, on n's side):
/// p G1(v) D(h) / (4 n.v) + (1 - p) max(n.l, 0) / pi, p from
/// gltfSpecularLobeProbability. Integrates to 1 over the sphere.
inline float gltfMixturePdf(const glm::vec3& n, const glm::vec3& v, const glm::vec3& l,
                            const glm::vec3& baseColor, float metallic, float roughness) {
  const float p = gltfSpecularLobeProbability(glm::dot(n, v), baseColor, metallic);
  const float alpha = gltfAlpha(roughness);
  const float specular = p > 0.0f ? ggxVisibleReflectionPdf(n, v, l, alpha * alpha) : 0.0f;
  const float diffuse = std::max(glm::dot(n, l), 0.0f) / kGltfPi;
  return p * specular + (1.0f - p) * diffuse;
}

/// A direction drawn from the mixture: uLobe < p picks the GGX lobe (l =
/// v reflected about a visible normal drawn from u1, u2), else the cosine lobe
/// (cosineSampleHemisphere(n, u1, u2)). May lie below the surface (GGX lobe).
inline glm::vec3 sampleGltfMixture(const glm::vec3& n, const glm::vec3& v,
                                   const glm::vec3& baseColor, float metallic, float roughness,
                                   float uLobe, float u1, float u2) {
  const float p = gltfSpecularLobeProbability(glm::dot(n, v), baseColor, metallic);
  if (uLobe >= p) return cosineSampleHemisphere(n, u1, u2);
  glm::vec3 t, b;
  orthonormalBasis(n, t, b);
  const glm::vec3 vLocal(glm::dot(v, t), glm::dot(v, b), glm::dot(v, n));
  const glm::vec3 hLocal = sampleGgxVisibleNormal(vLocal, gltfAlpha(roughness), u1, u2);
  const glm::vec3 h = glm::normalize(t * hLocal.x + b * hLocal.y + n * hLocal.z);
  return glm::normalize(2.0f * glm::dot(v, h) * h - v);
}

/// One sampled continuation: the direction and f(l, v) cos(theta_l) / pdf(l),
/// the factor a path's throughput gains; weight 0 (end the path) when l lies
/// below the surface or the float limit above is hit.
struct GltfBounce {
  glm::vec3 direction{0.0f};
  glm::vec3 weight{0.0f};
};

/// Draws l from the mixture for the surface (n, baseColor, metallic,
/// roughness) seen from unit v on n's side, from three uniform numbers.
/// brdfClampPerSr > 0 bounds each channel of f in the weight (a glossy VPL's
/// render.indirect.vpl_brdf_clamp, as gltfVplBrdf bounds it in the gather).
inline GltfBounce sampleGltfBounce(const glm::vec3& n, const glm::vec3& v,
                                   const glm::vec3& baseColor, float metallic, float roughness,
                                   float uLobe, float u1, float u2, float brdfClampPerSr = 0.0f) {
  GltfBounce out;
  if (glm::dot(n, v) <= 0.0f) return out;
  out.direction = sampleGltfMixture(n, v, baseColor, metallic, roughness, uLobe, u1, u2);
  const float cosL = glm::dot(n, out.direction);
  if (cosL <= 0.0f) return out;
  const float pdf = gltfMixturePdf(n, v, out.direction, baseColor, metallic, roughness);
  const glm::vec3 f =
      gltfVplBrdf(n, out.direction, v, baseColor, metallic, roughness, brdfClampPerSr);
  const glm::vec3 w = f * (cosL / pdf);
  if (pdf > 0.0f && std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z)) out.weight = w;
  return out;
}

}  // namespace tofsim::physics
