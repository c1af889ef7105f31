// A VPL's visibility of a point, as the indirect gathers test it
// (indirect_gather.comp; medium_vpls.comp, issue 42): with EXACT_VISIBILITY
// a shadow ray through the scene's BVH between the offset ends, else the
// VPL's imperfect shadow map (the resident batch's, uVplStride floats
// each). With MEDIUM_VPLS (a scattering medium, capture::Medium::scatters) a
// medium VPL (zero normal) has no hemisphere to map: it is tested exactly
// whatever render.indirect.visibility says (the CPU backend does the same).
// Include after vpl.glsl.
#ifndef TOFSIM_VPL_VISIBILITY_GLSL
#define TOFSIM_VPL_VISIBILITY_GLSL

#if defined(EXACT_VISIBILITY) || defined(MEDIUM_VPLS)
#include "scene_geometry.glsl"
#endif
#ifndef EXACT_VISIBILITY
layout(std430, binding = TOFSIM_SSBO_ISM) readonly buffer Ism { float ism[]; };
uniform uint uVplStride;
uniform int uIsmResolution;
#endif
uniform float uSceneScale_m;

// Whether VPL `vpl` (ISM `ismIndex` of the batch) sees x (unit normal n, 0
// for a medium point) along unit d = (x - vpl) / dist, cosX x's receiver
// cosine toward the VPL; `iterations` counts a shadow ray's loop trips.
bool visible(uint ismIndex, Vpl vpl, vec3 x, vec3 n, vec3 d, float dist, float cosX,
             inout uint iterations) {
#ifndef EXACT_VISIBILITY
#ifdef MEDIUM_VPLS
  if (dot(vpl.normal.xyz, vpl.normal.xyz) != 0.0) {
#endif
    ivec2 texel = paraboloidTexel(vpl, d, uIsmResolution);
    float stored = ism[ismIndex * uVplStride + uint(texel.y * uIsmResolution + texel.x)];
    // One texel spans at most 4/R radians (at the paraboloid's centre).
    float bias = ismDepthBias(dist, cosX, 4.0 / float(uIsmResolution), 0.01 * uSceneScale_m);
    return dist - bias <= stored;
#ifdef MEDIUM_VPLS
  }
#endif
#endif
#if defined(EXACT_VISIBILITY) || defined(MEDIUM_VPLS)
  float eps = 1e-4 * uSceneScale_m;
  return !segmentOccluded(vpl.positionPath.xyz + vpl.normal.xyz * eps, x + n * eps, iterations);
#endif
}

#endif  // TOFSIM_VPL_VISIBILITY_GLSL
