#version 450 core
// Per-region media (issue 42's `media:`): each G-buffer sample's camera leg
// (x -> its camera end) and light leg (light -> x) through the regions, once
// per render (RegionLegs.cpp), for the gathers to read (region_sample_legs.glsl)
// instead of walking the regions' triangles per sample and per VPL. One
// thread per sample record (surface_samples.glsl's sampleRecordIndex: the N x
// N samples of every pixel, then with ADAPTIVE_SAMPLES every pixel's centre
// sample). Record 2i: the camera leg's transmittance (rgb) and the path it
// adds (w, medium_regions.glsl's extraPath_m); 2i + 1: the light leg's. A
// sample that sees nothing gets (1, 1, 1, 0) twice. The CPU backend's
// PixelSurface::regionCameraT, regionCameraExtra_m and CpuDirectGather's
// light leg. Two legs of at most render::kGlRegionTrianglesMax triangles stay
// far below llvmpipe's 65535 loop trips; the guard flag says otherwise.
layout(local_size_x = TOFSIM_WORK_GROUP_SIZE) in;

#include "surface_samples.glsl"
#include "medium_regions.glsl"

uniform uint uRecordCount;  // sample records: pixels N^2 (+ pixels with ADAPTIVE_SAMPLES)
uniform int uImageWidth;
uniform vec3 uLightPosition_world;
#include "camera_end.glsl"

layout(std430, binding = TOFSIM_SSBO_REGION_LEGS) writeonly buffer RegionLegs {
  vec4 regionLegs[];
};
// 1: near llvmpipe's loop-trip limit; 2: a leg crossed a region more often
// than kRegionCrossings.
layout(std430, binding = TOFSIM_SSBO_LOOP_GUARD) buffer LoopGuard { uint loopLimitHit; };
const uint kLoopTripLimit = 30000u;

void main() {
  uint i = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
  if (i >= uRecordCount) return;
  uint fine = uImagePixels * uint(kSamplesPerPixel);
  uint pixel = i < fine ? i / uint(kSamplesPerPixel) : i - fine;
  int samples = i < fine ? kSamplesPerPixel : 1;
  int s = i < fine ? int(i % uint(kSamplesPerPixel)) : 0;
  ivec2 xy = ivec2(int(pixel % uint(uImageWidth)), int(pixel / uint(uImageWidth)));
  SurfaceSample g = pixelSample(xy, samples, s);
  vec4 cameraLeg = vec4(1.0, 1.0, 1.0, 0.0), lightLeg = vec4(1.0, 1.0, 1.0, 0.0);
  if (g.position.w != 0.0) {
    uint iterations = 0u;
    bool overflow = false;
    vec3 x = g.position.xyz;
    RegionPassage camera = regionPassage(x, cameraEndOf(xy, samples, s).position, iterations,
                                         overflow);
    RegionPassage light = regionPassage(uLightPosition_world, x, iterations, overflow);
    cameraLeg = vec4(regionTransmittance(camera), camera.extraPath_m);
    lightLeg = vec4(regionTransmittance(light), light.extraPath_m);
    if (iterations >= kLoopTripLimit) atomicOr(loopLimitHit, 1u);
    if (overflow) atomicOr(loopLimitHit, 2u);
  }
  regionLegs[2u * i] = cameraLeg;
  regionLegs[2u * i + 1u] = lightLeg;
}
