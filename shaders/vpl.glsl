// Virtual point lights from the reflective shadow map (Vpls.cpp) and the
// paraboloid parametrisation of their imperfect shadow maps.
struct Vpl {
  vec4 positionPath;  // xyz world position; w = optical path light -> VPL, metres
  vec4 normal;        // xyz unit normal on the lit side
  vec4 flux;          // rgb: albedo * flux / pi, W/sr (cosine-weighted intensity);
                      //   GLTF_MATERIALS: the power the VPL received, W
  vec4 patchU;        // the VPL's RSM texel patch: xyz step across it, w the light leg's path change
  vec4 patchV;        //   (ir::Vpl; footprint_kernel.glsl's vplPatchPathSteps)
#ifdef GLTF_MATERIALS
  vec4 incoming;      // xyz unit direction toward where the VPL's light came from; w metallic
  vec4 material;      // rgb base colour, w roughness
#endif
};
layout(std430, binding = TOFSIM_SSBO_VPLS) readonly buffer Vpls { Vpl vpls[]; };

#include "transient_physics.glsl"

// Texel of direction d (unit, world) in the VPL's hemisphere map; d must lie
// on the side of the normal.
ivec2 paraboloidTexel(Vpl vpl, vec3 d, int resolution) {
  return paraboloidTexelOf(vpl.normal.xyz, d, resolution);
}
