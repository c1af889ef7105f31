// Virtual point lights from the reflective shadow map (Vpls.cpp) and the
// paraboloid parametrisation of their imperfect shadow maps.
#include "transient_physics.glsl"
#include "scatter_vertex.glsl"

// ir::Vpl (std430, asserted there). Without VPL_VERTICES the buffer holds
// each VPL's first five members only (IndirectLight.cpp: every VPL's
// scatter is in its flux, so the gather reads no more than it did before).
// VPL_VERTICES (gpu::gatherDefines, ir::vplsCarryVertex): render.materials:
// gltf, or a scattering medium (its medium VPLs scatter by their phase).
struct Vpl {
  vec4 positionPath;  // xyz world position; w = optical path light -> VPL, metres
  vec4 normal;        // xyz unit normal on the lit side
  vec4 flux;          // rgb: albedo * flux / pi, W/sr (cosine-weighted intensity) where
                      //   vplFluxHoldsScatter(vertex); else the power the VPL received, W
  vec4 patchU;        // the VPL's RSM texel patch: xyz step across it, w the light leg's path change
  vec4 patchV;        //   (ir::Vpl; footprint_kernel.glsl's vplPatchPathSteps)
#ifdef VPL_VERTICES
  vec4 incoming;         // xyz unit direction toward where the VPL's light came from
  ScatterVertex vertex;  // what it scatters (scatter_vertex.glsl)
#endif
};
layout(std430, binding = TOFSIM_SSBO_VPLS) readonly buffer Vpls { Vpl vpls[]; };

#ifdef VPL_VERTICES
uniform float uVplBrdfClamp;  // 1/sr, <= 0: no clamping
#endif

// The radiance toward the camera at x from the VPL, along unit d (VPL -> x),
// with fCamera x's scatter toward the camera and g the geometry term
// (transient_physics.glsl's vplRadiance, with vplScatter's factor).
vec3 vplRadianceAt(Vpl vpl, vec3 fCamera, vec3 d, float g) {
#ifdef VPL_VERTICES
  vec3 fVpl = vplScatter(vpl.vertex, vpl.normal.xyz, vpl.incoming.xyz, d, uVplBrdfClamp);
  return vplRadiance(fCamera, fVpl, vpl.flux.rgb, g);
#else
  // The records without their vertex: its scatter is in the flux. Not a
  // product with fVpl = 1: Mesa's NIR reassociates such a product (its
  // constant moves), and the bytes would change.
  return fCamera * vpl.flux.rgb * g;
#endif
}

// Texel of direction d (unit, world) in the VPL's hemisphere map; d must lie
// on the side of the normal.
ivec2 paraboloidTexel(Vpl vpl, vec3 d, int resolution) {
  return paraboloidTexelOf(vpl.normal.xyz, d, resolution);
}
