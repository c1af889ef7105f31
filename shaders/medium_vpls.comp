#version 450 core
// The VPLs' light the medium scatters once into the camera rays (issue 42,
// item 4): every VPL of the dispatch is an emitter for medium.glsl's single
// scattering quadrature along each pixel sample's camera ray (before its
// first surface, or along the whole ray when it sees none), per time bin:
// its intensity toward the node (vplIntensityToward: a surface VPL's cosine
// emitter or BRDF, a medium VPL's albedo x phase), its 1/r^2 bounded by the
// geometry clamp (uVplRadius: mediumVplRadius), its light starting at its
// optical path, its visibility the batch's (vpl_visibility.glsl: the ISMs or
// the BVH, as indirect_gather.comp's). One thread per pixel, VPL by VPL in
// index order, then sample by sample, into its own volume and off-axis sums
// (MediumVpls.cpp adds them to the indirect light at read-back).
// core/cpu/src/CpuMediumVpls.cpp is the CPU twin; the physics:
// core/physics/medium_vpl_scattering.md.
layout(local_size_x = TOFSIM_WORK_GROUP_SIZE) in;

#include "transient_physics.glsl"
#include "random.glsl"
#include "vpl.glsl"
#include "surface_samples.glsl"
#include "medium_uniforms.glsl"

layout(std430, binding = TOFSIM_SSBO_MEDIUM_VPL_VOLUME) buffer MediumVplVolume {
  float mediumVplLight[];
};
layout(std430, binding = TOFSIM_SSBO_MEDIUM_VPL_OUTSIDE) buffer MediumVplOutside {
  float outside[];
};

uniform uint uFirstPixel;
uniform uint uPixelCount;
uniform int uImageWidth;
uniform int uBins;
uniform float uStart_m;
uniform float uBinWidth_m;
uniform float uIndexOfRefraction;
uniform int uCameraUnwarp;
uniform uint uFirstVpl;     // first VPL of this dispatch
uniform uint uVplCount;     // VPLs in this dispatch
uniform uint uIsmFirstVpl;  // first VPL whose ISM is at the start of the ISM buffer
uniform float uVplRadius;   // mediumVplRadius of render.indirect's geometry clamp, m
uniform float uMediumRayThreshold;  // the pairs' roulette (ir::mediumRayThreshold)
uniform uint uMediumRaySeed;        // the pairs' draws (ir::mediumRaySeed)
#include "camera_end.glsl"
#include "vpl_visibility.glsl"

// llvmpipe's loop-trip limit (indirect_gather.comp's guard): MediumVpls.cpp
// dispatches one VPL at a time; an invocation that still comes within a
// factor of two of the limit (many bins, many samples, exact visibility's
// shadow rays per node) raises the flag, and the render fails loudly.
const uint kLoopTripLimit = 30000u;
layout(std430, binding = TOFSIM_SSBO_LOOP_GUARD) buffer LoopGuard { uint loopLimitHit; };
uint gIterations = 0u;

#define GATHER_HISTOGRAM mediumVplLight
#include "bin_deposit.glsl"
#include "medium_sample_rays.glsl"

// VPL vpl's (ISM ismIndex) intensity toward the node, W/sr, and 0 where it
// does not see it.
vec3 vplNodeIntensity(Vpl vpl, uint ismIndex, MediumNode n) {
#ifdef VPL_VERTICES
  vec3 intensity = vplIntensityToward(vpl.vertex, vpl.normal.xyz, vpl.incoming.xyz, vpl.flux.rgb,
                                      n.fromLight, uVplBrdfClamp);
#else
  // Every VPL's scatter is in its flux (a Lambertian surface's intensity).
  vec3 intensity = vpl.flux.rgb * max(vplEmitterCosine(vpl.normal.xyz, n.fromLight), 0.0);
#endif
  if (intensity == vec3(0.0)) return vec3(0.0);
  if (!visible(ismIndex, vpl, n.x, vec3(0.0), n.fromLight, n.r, 1.0, gIterations)) {
    return vec3(0.0);
  }
  return intensity;
}

// Adds VPL vpl's sampled light along a ray (medium.glsl's
// mediumSampledInterval: its points at `offset` in their steps), times
// `weight`, into pixel `local`'s bins.
void gatherRay(uint local, Vpl vpl, uint ismIndex, MediumRay ray, float weight, float offset,
               inout float lostBefore, inout float lostAfter) {
  float start_m = uStart_m - vpl.positionPath.w;  // its light starts at its path
  ivec2 branches = mediumBranches(uCameraUnwarp != 0);
  for (int branch = branches.x; branch <= branches.y; ++branch) {
    vec2 span = mediumSpan(ray, branch);
    if (mediumSpanEmpty(span)) continue;
    MediumInterval iv = mediumSampledInterval(ray, span);
    for (int step = 0; step < iv.steps; ++step) {
      ++gIterations;
      MediumNode n = mediumNodeAt(ray, iv, step, vec2(offset, 1.0));
      if (n.weight == 0.0) continue;
      int k = mediumBinOf(ray, mediumPathAt(ray, branch, n.s), uIndexOfRefraction, start_m,
                          uBinWidth_m, uBins);
      vec3 light = mediumNodeRadiance(n, uMediumSigmaS, uMediumSigmaT, uMediumPhase, uMediumG,
                                      vplNodeIntensity(vpl, ismIndex, n), 1.0);
      depositInBin(local, k, 1.0, light * weight, lostBefore, lostAfter);
    }
  }
}

void main() {
  uint local = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
  if (local >= uPixelCount) return;
  uint pixel = uFirstPixel + local;
  ivec2 xy = ivec2(int(pixel % uint(uImageWidth)), int(pixel / uint(uImageWidth)));
  float lostBefore = outside[2u * local];
  float lostAfter = outside[2u * local + 1u];
  int samples = samplesOfPixel(pixel);
  for (uint k = 0u; k < uVplCount; ++k) {
    ++gIterations;
    Vpl vpl = vpls[uFirstVpl + k];
    uint ismIndex = uFirstVpl - uIsmFirstVpl + k;
    float importance = mediumRayVplImportance(vpl.flux.rgb, vpl.normal.xyz);
    for (int s = 0; s < samples; ++s) {
      float weight;
      MediumRay ray = mediumSampleRay(xy, samples, s, vpl.positionPath.xyz, uVplRadius, weight);
      // The pair's draws (CpuMediumVpls.cpp's): kept or not, its points' offset.
      uint bits = hash3(uFirstVpl + k, pixel, uMediumRaySeed + uint(s) * 0x9e3779b9u);
      float q = mediumRayVplSurvival(mediumRayVplEstimate(ray, importance), uMediumRayThreshold);
      if (!(unitFloat(bits) < q)) continue;
      gatherRay(local, vpl, ismIndex, ray, weight / q, unitFloat(pcgHash(bits)), lostBefore,
                lostAfter);
    }
  }
  outside[2u * local] = lostBefore;
  outside[2u * local + 1u] = lostAfter;
  if (gIterations >= kLoopTripLimit) atomicOr(loopLimitHit, 1u);
}
