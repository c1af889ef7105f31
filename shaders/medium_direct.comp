#version 450 core
// The medium's direct light (issue 42, item 3): the light the homogeneous
// medium filling the scene scatters once into each pixel sample's camera ray
// before its first surface (or along the whole ray when it sees none), per
// time bin, by medium.glsl's quadrature; the light's visibility at each node
// is the shadow map's (visibleFromLight, no surface normal: cosine 1). One
// thread per pixel of the segment, over its samples as direct_gather.comp
// takes them, after it: the light is added into the same direct volume and
// off-axis sums, each bin by this thread only. core/cpu/src/
// CpuMediumDirect.cpp is the CPU twin; core/render/src/MediumDirect.cpp runs
// this. A sample's ray starts at its camera end (camera_end.glsl) along its
// direction (uMediumRays: ir::sampleRay's, laid out as the camera ends).
layout(local_size_x = TOFSIM_WORK_GROUP_SIZE) in;

#include "surface_samples.glsl"
#include "light.glsl"

layout(std430, binding = TOFSIM_SSBO_DIRECT_VOLUME) buffer DirectVolume { float direct[]; };
layout(std430, binding = TOFSIM_SSBO_OUTSIDE_AXIS) buffer OutsideAxis { float outside[]; };

uniform uint uFirstPixel;
uniform uint uPixelCount;
uniform int uImageWidth;
uniform int uBins;
uniform float uStart_m;
uniform float uBinWidth_m;
uniform float uIndexOfRefraction;
uniform int uCameraUnwarp;
// The medium (capture::Medium): uMediumSigmaS/T, uMediumPhase, uMediumG
// (compiled with MEDIUM: gpu::gatherDefines; set by MediumUniforms.cpp).
#include "medium_uniforms.glsl"
#include "camera_end.glsl"

#define GATHER_HISTOGRAM direct
#include "bin_deposit.glsl"
#include "medium_sample_rays.glsl"


// The light of bin k's part of the ray (k: -1 before the axis, uBins after).
vec3 mediumBinLight(MediumRay ray, int branch, vec2 span, int k) {
  MediumInterval iv = mediumInterval(
      ray, mediumBinSpan(ray, branch, span, k, uIndexOfRefraction, uStart_m, uBinWidth_m, uBins));
  vec3 sum = vec3(0.0);
  for (int node = 0; node < iv.steps * iv.nodes; ++node) {
    MediumNode n = mediumNode(ray, iv, node);
    float profile = lightProfile(uLightProfile, uLightDirection_world, uSpotCosOuter,
                                 uSpotCosInner, n.fromLight);
    if (profile <= 0.0 || n.weight == 0.0 || !visibleFromLight(n.x, 1.0)) continue;
    sum += mediumNodeRadiance(n, uMediumSigmaS, uMediumSigmaT, uMediumPhase, uMediumG,
                              uLightIntensity_W_per_sr, profile);
  }
  return sum;
}

// Adds a ray's medium light, times `weight` (its share of the pixel), into
// pixel `local`'s bins.
void gatherRay(uint local, MediumRay ray, float weight, inout float lostBefore,
               inout float lostAfter) {
  ivec2 branches = mediumBranches(uCameraUnwarp != 0);
  for (int branch = branches.x; branch <= branches.y; ++branch) {
    vec2 span = mediumSpan(ray, branch);
    if (mediumSpanEmpty(span)) continue;
    ivec2 bins = mediumBinRange(ray, branch, span, uIndexOfRefraction, uStart_m, uBinWidth_m,
                                uBins);
    int step = bins.y >= bins.x ? 1 : -1;
    for (int k = bins.x;; k += step) {
      depositInBin(local, k, 1.0, mediumBinLight(ray, branch, span, k) * weight, lostBefore,
                   lostAfter);
      if (k == bins.y) break;
    }
  }
}

void gatherSample(uint local, ivec2 xy, int samples, int s, inout float lostBefore,
                  inout float lostAfter) {
  float weight;
  MediumRay ray = mediumSampleRay(xy, samples, s, uLightPosition_world, MEDIUM_EMITTER_RADIUS_M,
                                  weight);
  gatherRay(local, ray, weight, lostBefore, lostAfter);
}

void main() {
  uint local = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
  if (local >= uPixelCount) return;
  uint pixel = uFirstPixel + local;
  ivec2 xy = ivec2(int(pixel % uint(uImageWidth)), int(pixel / uint(uImageWidth)));
  float lostBefore = outside[2u * local];
  float lostAfter = outside[2u * local + 1u];
  int samples = samplesOfPixel(pixel);
  for (int s = 0; s < samples; ++s) gatherSample(local, xy, samples, s, lostBefore, lostAfter);
  outside[2u * local] = lostBefore;
  outside[2u * local + 1u] = lostAfter;
}
