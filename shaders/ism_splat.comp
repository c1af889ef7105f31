#version 450 core
// Imperfect shadow maps (Ritschel et al. 2008): each VPL of the batch gets
// its own random points on the scene's surfaces, splatted as one texel each
// into its paraboloid depth map. atomicMin on the distance's bits (positive
// floats order like unsigned integers) makes the result independent of
// thread order.
layout(local_size_x = TOFSIM_WORK_GROUP_SIZE) in;

#include "random.glsl"
#include "scene_geometry.glsl"
#include "vpl.glsl"

layout(std430, binding = TOFSIM_SSBO_ISM) buffer Ism { uint ism[]; };

uniform uint uFirstVpl;
uniform uint uVplCount;
uniform uint uPointsPerVpl;
uniform uint uVplStride;  // uints per VPL (all pull-push levels)
uniform int uIsmResolution;
uniform uint uSeed;

void main() {
  uint id = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
  if (id >= uVplCount * uPointsPerVpl) return;
  uint local = id / uPointsPerVpl;
  uint j = id % uPointsPerVpl;
  uint vplIndex = uFirstVpl + local;
  Vpl vpl = vpls[vplIndex];
  // A medium VPL (zero normal) has no hemisphere to map: the gather tests
  // it exactly (indirect_gather.comp's visible).
  if (dot(vpl.normal.xyz, vpl.normal.xyz) == 0.0) return;
  uint h0 = hash3(uSeed, vplIndex, j);
  uint h1 = pcgHash(h0), h2 = pcgHash(h1);
  vec3 p = sampleSurface(unitFloat(h0), unitFloat(h1), unitFloat(h2));
  vec3 d = p - vpl.positionPath.xyz;
  float dist = length(d);
  if (dist < 1e-6 || dot(d, vpl.normal.xyz) <= 0.0) return;
  ivec2 texel = paraboloidTexel(vpl, d / dist, uIsmResolution);
  atomicMin(ism[local * uVplStride + uint(texel.y * uIsmResolution + texel.x)], floatBitsToUint(dist));
}
