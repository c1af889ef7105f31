// The glTF metallic-roughness BRDF (the form of Khronos' glTF sample
// renderer, pinned by issue 16), written once in the common subset of GLSL
// 4.50 and C++/GLM with the rules of transient_physics.glsl: the GL gathers
// include this file, C++ includes it through
// core/physics/include/tofsim/physics/GltfBrdf.h.
//
// With n the unit normal, l and v the unit directions to the light and to the
// viewer, h = normalize(l + v) and alpha = roughness^2:
//   D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2)              (GGX)
//   V = 0.5 / ((n.l) sqrt((n.v)^2 (1 - alpha^2) + alpha^2)
//            + (n.v) sqrt((n.l)^2 (1 - alpha^2) + alpha^2))       (height-correlated Smith)
//   F(f0) = f0 + (1 - f0) (1 - |v.h|)^5                          (Schlick)
//   dielectric = (1 - F(0.04)) baseColor / pi + F(0.04) D V
//   metal = F(baseColor) D V
//   f = (1 - metallic) dielectric + metallic metal
// It is symmetric in l and v (|v.h| = |l.h|), and NOT Lambertian for any
// parameters: metallic 0, roughness 1 still carries the Fresnel-weighted GGX
// lobe and a diffuse term darkened by 1 - F(0.04). Energy: a white metal
// reflects at most what it receives; the dielectric mix does not at grazing
// views (its directional albedo reaches 1.22 at 80 degrees, roughness 0.3:
// tests/physics/GltfBrdfTest.cpp), a property of the pinned form, kept.
// Roughness is clamped below
// at kGltfMinRoughness so that a mirror (roughness 0) stays finite in float.
#ifndef TOFSIM_GLTF_BRDF_GLSL
#define TOFSIM_GLTF_BRDF_GLSL

#ifndef TOFSIM_PHYSICS_FN
#define TOFSIM_PHYSICS_FN
#endif

const float kGltfPi = 3.14159265358979323846f;
const float kGltfMinRoughness = 0.001f;
const float kGltfDielectricF0 = 0.04f;

// GGX normal distribution of the half vector, alpha2 = roughness^4.
TOFSIM_PHYSICS_FN float gltfGgxD(float nDotH, float alpha2) {
  float t = nDotH * nDotH * (alpha2 - 1.0f) + 1.0f;
  return alpha2 / (kGltfPi * t * t);
}

// Height-correlated Smith visibility G / (4 (n.l) (n.v)).
TOFSIM_PHYSICS_FN float gltfSmithV(float nDotL, float nDotV, float alpha2) {
  float towardsV = nDotL * sqrt(nDotV * nDotV * (1.0f - alpha2) + alpha2);
  float towardsL = nDotV * sqrt(nDotL * nDotL * (1.0f - alpha2) + alpha2);
  float sum = towardsV + towardsL;
  return sum > 0.0f ? 0.5f / sum : 0.0f;
}

// Schlick's Fresnel with reflectance f0 at normal incidence.
TOFSIM_PHYSICS_FN vec3 gltfSchlickF(vec3 f0, float vDotH) {
  float m = 1.0f - abs(vDotH);
  float m2 = m * m;
  return f0 + (vec3(1.0f) - f0) * (m2 * m2 * m);
}

// f(l, v) in 1/sr; 0 when l or v lies below the surface.
TOFSIM_PHYSICS_FN vec3 gltfBrdf(vec3 n, vec3 l, vec3 v, vec3 baseColor, float metallic,
                                float roughness) {
  float nDotL = dot(n, l);
  float nDotV = dot(n, v);
  if (nDotL <= 0.0f || nDotV <= 0.0f) return vec3(0.0f);
  vec3 h = normalize(l + v);
  float nDotH = max(dot(n, h), 0.0f);
  float vDotH = dot(v, h);
  float r = max(roughness, kGltfMinRoughness);
  float alpha = r * r;
  float alpha2 = alpha * alpha;
  float specular = gltfGgxD(nDotH, alpha2) * gltfSmithV(nDotL, nDotV, alpha2);
  vec3 fDielectric = gltfSchlickF(vec3(kGltfDielectricF0), vDotH);
  vec3 dielectric = (vec3(1.0f) - fDielectric) * baseColor / kGltfPi + fDielectric * specular;
  vec3 metal = gltfSchlickF(baseColor, vDotH) * specular;
  return (1.0f - metallic) * dielectric + metallic * metal;
}

// The BRDF value a glossy VPL gives the light it sends toward x: f(l, v) of
// the VPL's material for l = `incoming` (unit, toward where its light came
// from) and v = `toX` (unit, VPL -> x), each channel clamped at clampPerSr
// when that is positive (render.indirect.vpl_brdf_clamp: it bounds the spikes
// of smooth VPLs at the cost of the energy above the bound).
TOFSIM_PHYSICS_FN vec3 gltfVplBrdf(vec3 n, vec3 incoming, vec3 toX, vec3 baseColor, float metallic,
                                   float roughness, float clampPerSr) {
  vec3 f = gltfBrdf(n, incoming, toX, baseColor, metallic, roughness);
  if (clampPerSr > 0.0f) f = min(f, vec3(clampPerSr));
  return f;
}

#endif  // TOFSIM_GLTF_BRDF_GLSL
