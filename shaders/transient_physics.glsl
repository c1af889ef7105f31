// The per-contribution physics of transient instant radiosity, written once
// in the common subset of GLSL 4.50 and C++/GLM so the GL and the CPU
// backends cannot drift: the GL shaders #include this file through the shader
// assembly (core/gl/src/Program.cpp), C++ through
// core/physics/include/tofsim/physics/TransientPhysics.h, which maps vec3,
// floor, min... to GLM.
//
// Rules for this file: plain functions of scalars and vec3 only (no
// uniforms, buffers, out parameters or GLSL-only built-ins), float literals
// with an f suffix (C++ would otherwise compute in double), and every function prefixed
// by TOFSIM_PHYSICS_FN (empty in GLSL, `inline` in C++). Keep the order of
// the arithmetic: the GL volume's bytes depend on it.
#ifndef TOFSIM_TRANSIENT_PHYSICS_GLSL
#define TOFSIM_TRANSIENT_PHYSICS_GLSL

#ifndef TOFSIM_PHYSICS_FN
#define TOFSIM_PHYSICS_FN
#endif

const float PI = 3.14159265358979323846f;

// Fraction of a spot light's intensity emitted at cosine cosAngle from its
// axis: 1 inside the inner cone, 0 outside the outer one, smoothstep between.
TOFSIM_PHYSICS_FN float spotFalloff(float cosAngle, float cosOuter, float cosInner) {
  if (cosAngle >= cosInner) return 1.0f;
  if (cosAngle <= cosOuter) return 0.0f;
  float s = (cosAngle - cosOuter) / (cosInner - cosOuter);
  return s * s * (3.0f - 2.0f * s);
}

// The kinds of a light's angular profile (capture::Light::Type), as the
// gathers' uLightProfile holds them.
const int LIGHT_POINT = 0;
const int LIGHT_SPOT = 1;
const int LIGHT_LAMBERTIAN = 2;

// Fraction of a light's intensity emitted towards unit `direction`: 1 for a
// point light, the spot's falloff about its unit `axis`, the cosine about it
// for a Lambertian emitter (a laser spot on a wall).
TOFSIM_PHYSICS_FN float lightProfile(int kind, vec3 axis, float cosOuter, float cosInner,
                                     vec3 direction) {
  if (kind == LIGHT_POINT) return 1.0f;
  if (kind == LIGHT_LAMBERTIAN) return max(0.0f, dot(direction, axis));
  return spotFalloff(dot(direction, axis), cosOuter, cosInner);
}

// How the light reaches surface point x with unit normal n, before any
// visibility test: unit direction and distance to the light, the cosine at x
// and the light's profile towards x, which is 0 where x faces away from the
// light or lies outside its profile (nothing arrives then).
struct LightArrival {
  vec3 wLight;
  float dLight;
  float cosX;
  float profile;
};
TOFSIM_PHYSICS_FN LightArrival lightArrival(vec3 x, vec3 n, vec3 lightPosition, int kind,
                                            vec3 axis, float cosOuter, float cosInner) {
  LightArrival a;
  vec3 toLight = lightPosition - x;
  a.dLight = length(toLight);
  a.wLight = toLight / a.dLight;
  a.cosX = dot(n, a.wLight);
  a.profile = a.cosX <= 0.0f ? 0.0f : lightProfile(kind, axis, cosOuter, cosInner, -a.wLight);
  return a;
}

// Radiance a vertex that scatters by f (1/sr: scatter_vertex.glsl's
// scatter) at distance dLight from a point light of `intensity` (W/sr)
// sends toward the viewer, with cosX the cosine at the vertex and `profile`
// the light's angular profile.
TOFSIM_PHYSICS_FN vec3 directRadiance(vec3 f, vec3 intensity, float profile, float cosX,
                                      float dLight) {
  return f * intensity * (profile * cosX / (dLight * dLight));
}

// directRadiance of a Lambertian surface of `albedo` (f = albedo / pi).
TOFSIM_PHYSICS_FN vec3 lambertianDirect(vec3 albedo, vec3 intensity, float profile, float cosX,
                                        float dLight) {
  return directRadiance(albedo / PI, intensity, profile, cosX, dLight);
}

// Radiance toward the camera at x from a VPL that sends its flux (W/sr, or
// W with vplScatter's factor fVpl, 1/sr) toward x, with fCamera what x
// scatters toward the camera (scatter()'s f times the sample's share of the
// pixel) and g the geometry term cos cos / d^2 (clamped or not).
TOFSIM_PHYSICS_FN vec3 vplRadiance(vec3 fCamera, vec3 fVpl, vec3 flux, float g) {
  return fCamera * fVpl * flux * g;
}

// Optical path of the direct light: light -> x -> camera, times eta. dCamera
// is 0 when the camera delay is unwarped.
TOFSIM_PHYSICS_FN float directPathLength(float eta, float dLight, float dCamera) {
  return eta * (dLight + dCamera);
}

// Geometry term cos * cos / d^2 between a VPL and a surface point (1/m^2),
// clamped to `clampPerM2` when that is positive (it bounds the singularity
// near the VPL, at the cost of some energy).
TOFSIM_PHYSICS_FN float geometryTerm(float cosVpl, float cosX, float dist2, float clampPerM2) {
  float g = cosVpl * cosX / dist2;
  if (clampPerM2 > 0.0f) g = min(g, clampPerM2);
  return g;
}

// Optical path of the camera leg, 0 when the camera delay is unwarped.
TOFSIM_PHYSICS_FN float cameraPathLength(bool unwarp, float eta, float dCamera) {
  return unwarp ? 0.0f : eta * dCamera;
}

// Optical path of a VPL contribution: light -> VPL (vplPath, eta included),
// VPL -> x over `dist` in the medium, x -> camera (cameraPath, eta included).
TOFSIM_PHYSICS_FN float vplPathLength(float vplPath, float eta, float dist, float cameraPath) {
  return vplPath + eta * dist + cameraPath;
}

// Time bin of an optical path (metres): negative before the axis, >= bins after.
TOFSIM_PHYSICS_FN int binOfPath(float path_m, float start_m, float binWidth_m) {
  return int(floor((path_m - start_m) / binWidth_m));
}


// Orthonormal basis around n (Duff et al. 2017), columns tangent, bitangent, n.
TOFSIM_PHYSICS_FN mat3 basisAround(vec3 n) {
  float s = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (s + n.z);
  float b = n.x * n.y * a;
  vec3 t = vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
  vec3 bt = vec3(b, s + n.y * n.y * a, -n.y);
  return mat3(t, bt, n);
}

// Texel of unit direction d in the paraboloid map (side `resolution`) of the
// hemisphere around `normal`; d must lie on the side of the normal.
TOFSIM_PHYSICS_FN ivec2 paraboloidTexelOf(vec3 normal, vec3 d, int resolution) {
  vec3 local = transpose(basisAround(normal)) * d;
  vec2 uv = vec2(local.x, local.y) / (1.0f + max(local.z, 0.0f)) * 0.5f + 0.5f;
  return clamp(ivec2(uv * float(resolution)), ivec2(0), ivec2(resolution - 1));
}

// The steepest slope the ISM test's depth tolerance allows for (ismDepthBias):
// beyond it (receivers more than about 80 degrees from facing the VPL, whose
// light cos(alpha) makes small) a larger tolerance would let light through
// thin occluders.
const float kIsmMaxSlope = 8.0f;

// The imperfect shadow map's depth tolerance, metres: how much nearer than
// the receiver a texel's stored depth may be with the receiver still lit. A
// texel holds the nearest of the points splatted into its solid angle; on the
// receiver's own surface those lie up to the texel's diagonal (sqrt(2)
// texelAngle) away in direction, so up to dist sqrt(2) texelAngle tan(alpha)
// nearer, alpha the angle between the receiver's normal and the direction to
// the VPL (cosX = cos(alpha)). A tolerance without the slope hid visible VPLs
// from every receiver seen obliquely, more for the longer paths: IR's late
// light 9-12 % under exact visibility's (bench/README.md, "The ISM's bias").
// At least one texel's depth (dist texelAngle, the tolerance of before for a
// receiver that faces the VPL); sceneBias_m for the points' float spread.
TOFSIM_PHYSICS_FN float ismDepthBias(float dist, float cosX, float texelAngle, float sceneBias_m) {
  float c = max(cosX, 1e-6f);
  float slope = 1.41421356f * sqrt(max(1.0f - c * c, 0.0f)) / c;
  return dist * texelAngle * min(max(slope, 1.0f), kIsmMaxSlope) + sceneBias_m;
}

// Point of triangle (a, b, c) for two uniform numbers, uniform by area.
TOFSIM_PHYSICS_FN vec3 pointOnTriangle(vec3 a, vec3 b, vec3 c, float r1, float r2) {
  float s = sqrt(r1);
  return a * (1.0f - s) + b * (s * (1.0f - r2)) + c * (s * r2);
}

#endif
