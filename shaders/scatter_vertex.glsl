// The scattering vertex: what the transport needs to know of a point where
// light changes direction (a camera sample's surface point, a VPL, a point of
// a medium), declared once for both backends in the common subset of GLSL
// 4.50 and C++/GLM (the rules of transient_physics.glsl); C++ includes it
// through core/physics/include/tofsim/physics/ScatterVertex.h, which checks
// its layout (it is a member of the std430 VPL record, shaders/vpl.glsl).
//
// A gather never asks which material model a vertex has: it calls scatter()
// for the factor the light gains at the vertex, vertexLightArrival() for how
// the light reaches it, and vplScatter() for what a VPL sends on. The models
// are handled here only. A GL program whose vertices all have one model
// defines SCATTER_MODEL to it (GpuContract.cpp, from render.materials), so
// that its compiler folds the model's branches away.
#ifndef TOFSIM_SCATTER_VERTEX_GLSL
#define TOFSIM_SCATTER_VERTEX_GLSL

#ifndef TOFSIM_PHYSICS_FN
#define TOFSIM_PHYSICS_FN
#endif

#include "transient_physics.glsl"
#include "gltf_brdf.glsl"
#include "medium.glsl"

// Material models (ScatterVertex::model).
const int VERTEX_LAMBERTIAN = 0;  // albedo / pi (render.materials: lambertian)
const int VERTEX_GLTF = 1;        // the glTF metallic-roughness BRDF (gltf_brdf.glsl)
const int VERTEX_MEDIUM = 2;      // a point of a medium: albedo x phase function, no normal

// Temporal response classes (ScatterVertex::response): how long the vertex
// holds the light it scatters. Only RESPONSE_INSTANT today (issue 41).
const int RESPONSE_INSTANT = 0;

// 32 bytes, std430 and C++ alike (ScatterVertex.h asserts it).
struct ScatterVertex {
  vec4 color;           // rgb: Lambertian albedo, glTF base colour, or a medium's
                        //   single-scattering albedo; w: glTF metallic, or a
                        //   medium's phase model (PHASE_*, medium.glsl) as a float
  float roughness;      // glTF perceptual roughness; a medium's asymmetry g
  int model;            // VERTEX_*
  int response;         // RESPONSE_*: the class of its temporal response
  float responseParam;  // the response's parameter (none for RESPONSE_INSTANT)
};

// What scatter() returns: the factor the light gains at the vertex, and the
// temporal response it leaves with (always instant today).
struct Scattered {
  vec3 f;  // BRDF (1/sr) or albedo times phase function (1/sr)
  int response;
  float responseParam;
};

TOFSIM_PHYSICS_FN ScatterVertex scatterVertex(int model, vec3 color, float metallic,
                                              float roughness) {
  ScatterVertex v;
  v.color = vec4(color, metallic);
  v.roughness = roughness;
  v.model = model;
  v.response = RESPONSE_INSTANT;
  v.responseParam = 0.0f;
  return v;
}

// Vertex v (a material's, ir::materialVertex) at a point where its textures
// give baseColorTexel (rgb, 1 where it has no base-colour texture) and
// metallicRoughnessTexel (the texture's (b, g), 1 where none): the factors
// times the texels, glTF's rule. The one per-point step of a material, on a
// traced hit (ir::hitVertex) and a G-buffer texel (surface_samples.glsl).
TOFSIM_PHYSICS_FN ScatterVertex texturedVertex(ScatterVertex v, vec3 baseColorTexel,
                                               vec2 metallicRoughnessTexel) {
  v.color = vec4(vec3(v.color) * baseColorTexel, v.color.w * metallicRoughnessTexel.x);
  v.roughness = v.roughness * metallicRoughnessTexel.y;
  return v;
}

// A point of a medium (VERTEX_MEDIUM) of single-scattering albedo `albedo`
// whose phase function is model `phase` (PHASE_*) with asymmetry g.
TOFSIM_PHYSICS_FN ScatterVertex mediumVertex(vec3 albedo, int phase, float g) {
  return scatterVertex(VERTEX_MEDIUM, albedo, float(phase), g);
}

// The vertex's model; a compile-time constant in a program that defines
// SCATTER_MODEL.
TOFSIM_PHYSICS_FN int vertexModel(ScatterVertex v) {
#ifdef SCATTER_MODEL
  return SCATTER_MODEL;
#else
  return v.model;
#endif
}

// Whether scatter() is the same for every pair of directions (a Lambertian
// surface, an isotropic medium): a gather may then evaluate it once per
// vertex instead of once per contribution.
TOFSIM_PHYSICS_FN bool scatterIsConstant(ScatterVertex v) {
  int model = vertexModel(v);
  if (model == VERTEX_MEDIUM) return int(v.color.w) == PHASE_ISOTROPIC;
  return model != VERTEX_GLTF;
}

// The light that arrives at the vertex from unit direction wi (toward where
// it came from) and leaves toward unit wo, with n the surface's unit normal
// (ignored by a medium point): f, in the order of the products the gathers
// computed before (albedo / pi; gltfBrdf(n, wi, wo, ...)).
TOFSIM_PHYSICS_FN Scattered scatter(ScatterVertex v, vec3 n, vec3 wi, vec3 wo) {
  Scattered s;
  s.response = v.response;
  s.responseParam = v.responseParam;
  int model = vertexModel(v);
  if (model == VERTEX_GLTF) {
    s.f = gltfBrdf(n, wi, wo, vec3(v.color), v.color.w, v.roughness);
  } else if (model == VERTEX_MEDIUM) {
    // The isotropic phase as before (the same floats), any other by its law.
    int phase = int(v.color.w);
    s.f = phase == PHASE_ISOTROPIC ? vec3(v.color) / (4.0f * PI)
                                   : vec3(v.color) * phaseFunction(phase, v.roughness, dot(-wi, wo));
  } else {
    s.f = vec3(v.color) / PI;
  }
  return s;
}

// Whether the vertex lies on a surface: it has a normal, a tangent plane and
// a side. A medium point (VERTEX_MEDIUM) has none of them: what it shares
// with a surface point on its way through the gathers, and what differs,
// function by function, is core/physics/medium_points.md.
TOFSIM_PHYSICS_FN bool vertexOnSurface(ScatterVertex v) {
  return vertexModel(v) != VERTEX_MEDIUM;
}

// The cosine a VPL with unit normal n (zero for a medium VPL, ir/MediumVpl.h)
// weighs its light toward unit d (VPL -> x) with: n . d at a surface VPL, 1 at
// a medium VPL, which has no side (its phase function is in its scatter()).
TOFSIM_PHYSICS_FN float vplEmitterCosine(vec3 n, vec3 d) {
  return dot(n, n) == 0.0f ? 1.0f : dot(n, d);
}

// The cosine a vertex weighs light arriving along unit w (toward the light)
// with: n . w on a surface, 1 in a medium (a phase function, no normal).
TOFSIM_PHYSICS_FN float receiverCosine(ScatterVertex v, vec3 n, vec3 w) {
  return vertexModel(v) == VERTEX_MEDIUM ? 1.0f : dot(n, w);
}

// receiverCosine with no branch per direction, for a gather that weighs many
// directions at one vertex (the CPU's vectorised VPL lanes): it equals
//   receiverCosineOffset(v) + dot(receiverNormal(v, n), w),
// with the vertex's normal zeroed on a medium point and 1 added there (on a
// surface the offset is 0, and 0 - a = -a exactly: the same floats).
TOFSIM_PHYSICS_FN vec3 receiverNormal(ScatterVertex v, vec3 n) {
  return vertexOnSurface(v) ? n : vec3(0.0f);
}

TOFSIM_PHYSICS_FN float receiverCosineOffset(ScatterVertex v) {
  return vertexOnSurface(v) ? 0.0f : 1.0f;
}

// The normal of the plane a pixel's footprint is measured in at the vertex
// (surfaceStepAcrossPixel, footprint_kernel.glsl): a surface's tangent plane
// (n), or for a medium point the plane through it normal to the camera ray
// (unit direction `ray`): the ray's cross-section at its distance, the area
// the pixel's cone covers there. (Its extent along the ray, the depth a
// medium sample stands for, is the driver's to spread in time: the samples'
// own weights and path times, issue 42.)
TOFSIM_PHYSICS_FN vec3 footprintPlaneNormal(ScatterVertex v, vec3 n, vec3 ray) {
  return vertexOnSurface(v) ? n : ray;
}

// lightArrival (transient_physics.glsl) at vertex v: a medium point takes the
// light from every direction, with no cosine.
TOFSIM_PHYSICS_FN LightArrival vertexLightArrival(ScatterVertex v, vec3 x, vec3 n,
                                                  vec3 lightPosition, int kind, vec3 axis,
                                                  float cosOuter, float cosInner) {
  LightArrival a = lightArrival(x, n, lightPosition, kind, axis, cosOuter, cosInner);
  if (vertexModel(v) == VERTEX_MEDIUM) {
    a.cosX = 1.0f;
    a.profile = lightProfile(kind, axis, cosOuter, cosInner, -a.wLight);
  }
  return a;
}

// Whether a VPL of this vertex carries its scatter in its flux: a Lambertian
// VPL is the cosine emitter albedo Phi / pi (W/sr) and scatters by 1; any
// other VPL's flux is the power it received (W), scattered by vplScatter.
TOFSIM_PHYSICS_FN bool vplFluxHoldsScatter(ScatterVertex v) {
  return vertexModel(v) == VERTEX_LAMBERTIAN;
}

// What a VPL of vertex v (unit normal n) that received its light from unit
// `incoming` (toward where it came from) gives toward unit toX: 1 when its
// flux holds it (vplFluxHoldsScatter), else scatter()'s f, each channel
// clamped at clampPerSr when that is positive
// (render.indirect.vpl_brdf_clamp: it bounds the spikes of smooth VPLs).
TOFSIM_PHYSICS_FN vec3 vplScatter(ScatterVertex v, vec3 n, vec3 incoming, vec3 toX,
                                  float clampPerSr) {
  if (vplFluxHoldsScatter(v)) return vec3(1.0f);
  vec3 f = scatter(v, n, incoming, toX).f;
  if (clampPerSr > 0.0f) f = min(f, vec3(clampPerSr));
  return f;
}

// A VPL's intensity toward unit u, W/sr (the medium's light along a camera
// ray, issue 42 item 4): flux x vplScatter x its emitter cosine, 0 behind a
// surface VPL (a medium VPL has no side: vplEmitterCosine is 1).
TOFSIM_PHYSICS_FN vec3 vplIntensityToward(ScatterVertex v, vec3 n, vec3 incoming, vec3 flux,
                                          vec3 u, float clampPerSr) {
  float cosine = vplEmitterCosine(n, u);
  if (cosine <= 0.0f) return vec3(0.0f);
  return flux * vplScatter(v, n, incoming, u, clampPerSr) * cosine;
}

#endif  // TOFSIM_SCATTER_VERTEX_GLSL
