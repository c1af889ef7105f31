#version 450 core
// Direct transient light: one thread per pixel of the segment, over the
// pixel's G-buffer samples in order: its PIXEL_SAMPLES^2 sub-pixel samples, or
// with ADAPTIVE_SAMPLES one centre sample where the mask says so
// (surface_samples.glsl). A sample's point x receives the light's impulse
// after |l - x| and scatters it (its vertex's scatter(), scatter_vertex.glsl)
// to the camera after |x - c|; the radiance
// lands in the bin of the full optical path eta * (|l - x| + |x - c|), or
// eta * |l - x| when the camera delay is unwarped. With PIXEL_FOOTPRINT it is
// spread instead over that path's distribution across the sample's footprint
// (its sub-pixel, or the whole pixel for a centre sample;
// footprint_deposit.glsl). With MEDIUM (a medium filling the scene) the
// radiance is attenuated over both legs (medium_uniforms.glsl); with
// MEDIUM_REGIONS (per-region media) over both legs' passages through the
// regions, whose index adds their time (region_legs.comp found them: the
// footprint is centred on the delayed path). Each bin
// has this thread as its only writer, so the result does not depend on
// scheduling. With RESPONSE_CLASSES (a render with
// scattering delays) the light of a delayed surface goes to its class's
// buffer instead (response_classes.glsl), point samples as spikes. The
// sample loop runs at most 16^2 times, far below llvmpipe's 65535 loop trips
// per invocation.
layout(local_size_x = TOFSIM_WORK_GROUP_SIZE) in;

#include "surface_samples.glsl"
#include "light.glsl"
#include "medium_uniforms.glsl"
#include "region_sample_legs.glsl"

layout(std430, binding = TOFSIM_SSBO_DIRECT_VOLUME) buffer DirectVolume { float direct[]; };
layout(std430, binding = TOFSIM_SSBO_OUTSIDE_AXIS) buffer OutsideAxis { float outside[]; };  // [2 * pixel]: before, [2 * pixel + 1]: after

uniform uint uFirstPixel;
uniform uint uPixelCount;
uniform int uImageWidth;
uniform int uBins;
uniform float uStart_m;
uniform float uBinWidth_m;
uniform float uIndexOfRefraction;
uniform int uCameraUnwarp;
#include "camera_end.glsl"

#define GATHER_HISTOGRAM direct
#include "bin_deposit.glsl"
#if defined(PIXEL_FOOTPRINT) || defined(RESPONSE_CLASSES)
#include "footprint_deposit.glsl"
#endif
#ifdef RESPONSE_CLASSES
#include "response_classes.glsl"
#endif

// Adds sample s of pixel `local` (image pixel `pixel` at xy, which takes
// `samples`).
void gatherSample(uint local, uint pixel, ivec2 xy, int samples, int s, inout float lostBefore,
                  inout float lostAfter) {
  SurfaceSample g = pixelSample(xy, samples, s);
  if (g.position.w == 0.0) return;
  CameraEnd end = cameraEndOf(xy, samples, s);
  vec3 x = g.position.xyz;
  vec3 n = g.normal;

  LightArrival arrival = arrivalAt(g.vertex, x, n);
  float profile = arrival.profile, cosX = arrival.cosX, dLight = arrival.dLight;
  vec3 wLight = arrival.wLight;
  if (profile <= 0.0 || !visibleFromLight(x, cosX)) return;

  vec3 camera = end.position;
  vec3 wCamera = normalize(camera - x);
  vec3 radiance = directRadiance(scatter(g.vertex, n, wLight, wCamera).f,
                                 uLightIntensity_W_per_sr, profile, cosX, dLight);
#ifdef SAMPLE_CAMERA_ENDS
  float dCamera = uCameraUnwarp != 0 ? 0.0 : length(x - camera) + end.lensPath_m;
#else
  float dCamera = uCameraUnwarp != 0 ? 0.0 : length(x - camera);
#endif
#ifdef MEDIUM_REGIONS
  // Both legs through the regions (CpuDirectGather's directLight): their
  // transmittance, and the time inside them (the camera leg's unless unwarped).
  SampleLegs legs = sampleLegs(pixel, samples, s);
  radiance *= legs.lightT * legs.cameraT;
  float path_m = directPathLength(uIndexOfRefraction, dLight + legs.lightExtra_m,
                                  uCameraUnwarp != 0 ? dCamera : dCamera + legs.cameraExtra_m);
#else
  float path_m = directPathLength(uIndexOfRefraction, dLight, dCamera);
#endif
#ifdef MEDIUM
  // The light -> x and x -> camera legs, the latter whatever the unwarp
  // (the lens's path is inside the camera).
  radiance *= mediumLegsTransmittance(dLight + length(x - camera));
#endif
#ifdef RESPONSE_CLASSES
  // The light of a delayed surface: into its class's buffer, whatever the
  // footprint setting (response_classes.glsl).
  uint responseClass = responseClassSingle(g.vertex.response);
#endif
#ifdef PIXEL_FOOTPRINT
  vec3 dxdu, dxdv;
  surfaceStepsAcrossSample(x, footprintPlaneNormal(g.vertex, n, -wCamera), camera, g.pixel,
                           g.wholePixel, dxdu, dxdv);
  vec2 steps = pathStepsAcrossPixel(
      opticalPathGradient(x, uLightPosition_world, camera, uIndexOfRefraction,
                          uCameraUnwarp != 0),
      dxdu, dxdv);
  vec3 kernel = footprintKernel(path_m, steps, uStart_m, uBinWidth_m);
#ifdef RESPONSE_CLASSES
  if (responseClass != 0u) {
    depositDelayed(local, responseClass, kernel, radiance * g.weight, lostBefore, lostAfter);
    return;
  }
#endif
  depositContribution(local, kernel, radiance * g.weight, lostBefore, lostAfter);
#else
  // Point sampling: one sample gives the bytes of before sub-pixel samples.
#if PIXEL_SAMPLES > 1
  radiance = radiance * g.weight;
#endif
#ifdef RESPONSE_CLASSES
  if (responseClass != 0u) {
    // A point sample's path is a spike at path_m.
    depositDelayed(local, responseClass, footprintKernel(path_m, vec2(0.0), uStart_m, uBinWidth_m),
                   radiance, lostBefore, lostAfter);
    return;
  }
#endif
  depositInBin(local, binOfPath(path_m, uStart_m, uBinWidth_m), 1.0, radiance, lostBefore,
               lostAfter);
#endif
}

void main() {
  uint local = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
  if (local >= uPixelCount) return;
  uint pixel = uFirstPixel + local;
  ivec2 xy = ivec2(int(pixel % uint(uImageWidth)), int(pixel / uint(uImageWidth)));
  float lostBefore = outside[2u * local];
  float lostAfter = outside[2u * local + 1u];
#if PIXEL_SAMPLES == 1
  gatherSample(local, pixel, xy, 1, 0, lostBefore, lostAfter);
#else
  int samples = samplesOfPixel(pixel);
  for (int s = 0; s < samples; ++s) {
    gatherSample(local, pixel, xy, samples, s, lostBefore, lostAfter);
  }
#endif
  outside[2u * local] = lostBefore;
  outside[2u * local + 1u] = lostAfter;
}
