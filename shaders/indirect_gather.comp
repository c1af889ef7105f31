#version 450 core
// One indirect bounce (Eqs. 6, 7, 15, 17): one thread per pixel loops over the
// batch's VPLs in index order and, for each, over the pixel's G-buffer samples
// (its PIXEL_SAMPLES^2 sub-pixel samples, or with ADAPTIVE_SAMPLES one centre
// sample where the mask says so: surface_samples.glsl), and adds each
// contribution to the bin of its full optical path  t_l + eta (|x_l - x| +
// |x - c|); with PIXEL_FOOTPRINT it is spread over that path's distribution
// across the sample's footprint (its sub-pixel, or the whole pixel for a
// centre sample) and the VPL's patch (footprint_deposit.glsl). Being the
// only writer of its pixel's bins, and adding in a fixed order (VPL, then
// sample: an order that does not depend on where the batches and dispatches
// split the VPLs), makes the sum reproducible bit for bit whatever the batch
// and segment sizes. With RESPONSE_CLASSES (a render with scattering delays)
// a contribution of a delayed class (the VPL's, then the sample's vertex)
// goes to its class's buffer instead (response_classes.glsl). With MEDIUM
// (a medium filling the scene) each contribution is attenuated over its
// VPL -> x and x -> camera legs (medium_uniforms.glsl); with MEDIUM_REGIONS
// (per-region media) over those legs' passages through the regions, whose
// index adds their time (the VPL -> x leg's found here, medium_regions.glsl;
// the camera leg's by region_legs.comp; the light -> VPL leg's is in the
// VPL's flux and path): the footprint is centred on the delayed path.
// Both ends of a contribution scatter (scatter_vertex.glsl): the VPL toward x
// (vplScatterToward: 1 where its flux holds it), and x toward the camera for
// the direction to the VPL (scatter()).
layout(local_size_x = TOFSIM_WORK_GROUP_SIZE) in;

#include "transient_physics.glsl"
#include "vpl_near_field.glsl"
#include "vpl.glsl"

#include "surface_samples.glsl"
#include "medium_uniforms.glsl"
#include "medium_regions.glsl"
#include "region_sample_legs.glsl"

layout(std430, binding = TOFSIM_SSBO_INDIRECT_VOLUME) buffer IndirectVolume { float indirect[]; };
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
uniform uint uFirstVpl;     // first VPL of this dispatch
uniform uint uVplCount;     // VPLs in this dispatch
uniform uint uIsmFirstVpl;  // first VPL whose ISM is at the start of the ISM buffer
uniform float uGeometryClamp;  // <= 0: no clamping

#define GATHER_HISTOGRAM indirect
#include "bin_deposit.glsl"
#if defined(PIXEL_FOOTPRINT) || defined(RESPONSE_CLASSES)
#include "footprint_deposit.glsl"
#endif
#ifdef RESPONSE_CLASSES
#include "response_classes.glsl"
#endif

// llvmpipe stops every loop of an invocation after 65535 iterations in total
// (its infinite-loop guard), silently, and counts loop entries too. The
// renderer sizes dispatches to stay well below (counting the sample loop and
// the shadow rays per VPL: IndirectLight::vplsPerDispatch, for a pixel of
// PIXEL_SAMPLES^2 samples, the most any takes); an invocation that still
// comes within a factor of two raises this flag so the render fails loudly
// instead of losing light. With MEDIUM_REGIONS a leg that crosses a region's
// surface more often than the shader keeps raises 2 (medium_regions.glsl).
const uint kLoopTripLimit = 30000u;
layout(std430, binding = TOFSIM_SSBO_LOOP_GUARD) buffer LoopGuard { uint loopLimitHit; };

#include "vpl_visibility.glsl"

// One G-buffer sample as the gather uses it.
struct Sample {
  bool lit;  // a surface was seen
  vec3 x;
  vec3 n;
  ScatterVertex vertex;  // what x scatters
  vec3 camera;           // where its camera leg ends (camera_end.glsl)
  vec3 toCamera;         // unit, x -> camera
  float weight;          // the sample's share of the pixel (1 with one point sample)
  float cameraPath;   // eta |x - c|, or 0 when unwarped
#ifdef MEDIUM_REGIONS
  vec3 cameraT;       // the camera leg's transmittance through the regions
#endif
#ifdef PIXEL_FOOTPRINT
  vec3 dxdu, dxdv;    // the surface's steps across the sample's footprint
#endif
};

// Sample s of the pixel at xy, which takes `samples` (samplesOfPixel).
Sample loadSample(ivec2 xy, int samples, int s) {
  Sample o;
  SurfaceSample g = pixelSample(xy, samples, s);
  o.lit = g.position.w != 0.0;
  o.x = g.position.xyz;
  o.n = g.normal;
  o.vertex = g.vertex;
  CameraEnd end = cameraEndOf(xy, samples, s);
  o.camera = end.position;
  o.toCamera = normalize(o.camera - o.x);
#if defined(PIXEL_FOOTPRINT) || PIXEL_SAMPLES > 1
  o.weight = g.weight;  // as the CPU's PixelSurface::weight
#else
  o.weight = 1.0;
#endif
#if defined(MEDIUM_REGIONS)
  // The camera leg through the regions (CpuBackend::fillSurface): its
  // transmittance, and the time inside them.
  SampleLegs legs = sampleLegs(uint(xy.y * uImageWidth + xy.x), samples, s);
  o.cameraT = legs.cameraT;
  o.cameraPath = cameraPathLength(uCameraUnwarp != 0, uIndexOfRefraction,
                                  length(o.x - o.camera) + end.lensPath_m + legs.cameraExtra_m);
#elif defined(SAMPLE_CAMERA_ENDS)
  o.cameraPath = cameraPathLength(uCameraUnwarp != 0, uIndexOfRefraction,
                                  length(o.x - o.camera) + end.lensPath_m);
#else
  o.cameraPath = cameraPathLength(uCameraUnwarp != 0, uIndexOfRefraction,
                                  length(o.x - o.camera));
#endif
#ifdef PIXEL_FOOTPRINT
  surfaceStepsAcrossSample(o.x, footprintPlaneNormal(o.vertex, o.n, -o.toCamera), o.camera,
                           g.pixel, g.wholePixel, o.dxdu, o.dxdv);
#endif
  return o;
}

// Adds VPL k of the dispatch (vpl) seen from sample `at` of pixel `local`.
void gatherVpl(uint local, Sample at, uint k, Vpl vpl, inout float lostBefore,
               inout float lostAfter, inout uint iterations) {
  vec3 toX = at.x - vpl.positionPath.xyz;
  float dist2 = dot(toX, toX);
  if (dist2 <= 0.0) return;
  float dist = sqrt(dist2);
  vec3 d = toX / dist;
  float cosVpl = vplEmitterCosine(vpl.normal.xyz, d);  // 1 at a medium VPL
  float cosX = receiverCosine(at.vertex, at.n, -d);
  if (cosVpl <= 0.0 || cosX <= 0.0) return;
  float g = vertexOnSurface(at.vertex)
                ? vplGeometryTerm(cosVpl, cosX, dist2, uGeometryClamp, at.x, at.n,
                                  vpl.positionPath.xyz, vpl.patchU.xyz, vpl.patchV.xyz)
                : vplMediumGeometryTerm(cosVpl, dist2, uGeometryClamp, at.x, vpl.positionPath.xyz,
                                        vpl.patchU.xyz, vpl.patchV.xyz);
  if (!visible(uFirstVpl - uIsmFirstVpl + k, vpl, at.x, at.n, d, dist, cosX, iterations)) return;
  vec3 fCamera = scatter(at.vertex, at.n, -d, at.toCamera).f * at.weight;
  vec3 radiance = vplRadianceAt(vpl, fCamera, d, g);
#ifdef MEDIUM
  // The VPL -> x and x -> camera legs (the earlier ones are in the VPL's
  // flux), the latter whatever the unwarp.
  radiance *= mediumLegsTransmittance(dist + length(at.x - at.camera));
#endif
#ifdef MEDIUM_REGIONS
  // The VPL -> x leg through the regions (the CPU's GatherKernel regionLanes).
  bool overflow = false;
  RegionPassage leg = regionPassage(vpl.positionPath.xyz, at.x, iterations, overflow);
  if (overflow) atomicOr(loopLimitHit, 2u);
  radiance *= regionTransmittance(leg) * at.cameraT;
  float path_m = vplPathLength(vpl.positionPath.w, uIndexOfRefraction, dist + leg.extraPath_m,
                               at.cameraPath);
#else
  float path_m = vplPathLength(vpl.positionPath.w, uIndexOfRefraction, dist, at.cameraPath);
#endif
#ifdef RESPONSE_CLASSES
  // The VPL's class (its history, in flux.w) then the sample's vertex:
  // delayed light into its class's buffer, whatever the footprint setting.
  uint responseClass = responseClassThen(uint(vpl.flux.w), at.vertex.response);
#endif
#ifdef PIXEL_FOOTPRINT
  vec2 pixelSteps = pathStepsAcrossPixel(
      opticalPathGradient(at.x, vpl.positionPath.xyz, at.camera, uIndexOfRefraction,
                          uCameraUnwarp != 0),
      at.dxdu, at.dxdv);
#ifdef VPL_FOOTPRINT
  vec2 patchSteps = vplPatchPathSteps(vpl.patchU, vpl.patchV, d, uIndexOfRefraction);
#else
  vec2 patchSteps = vec2(0.0);
#endif
  vec3 kernel = footprintKernel(path_m, vec4(pixelSteps, patchSteps), uStart_m, uBinWidth_m);
#ifdef RESPONSE_CLASSES
  if (responseClass != 0u) {
    depositDelayed(local, responseClass, kernel, radiance, lostBefore, lostAfter);
    return;
  }
#endif
  depositContribution(local, kernel, radiance, lostBefore, lostAfter);
#else
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
#ifdef PIXEL_FOOTPRINT
  // The CPU's order: the off-axis sums carry on from the buffer's.
  float lostBefore = outside[2u * local];
  float lostAfter = outside[2u * local + 1u];
#else
  float lostBefore = 0.0;
  float lostAfter = 0.0;
#endif
  uint iterations = 0u;
#if PIXEL_SAMPLES == 1
  Sample at = loadSample(xy, 1, 0);
  if (!at.lit) return;
#else
  // A masked-out pixel's one centre sample goes through the loop below: the
  // additions of PIXEL_SAMPLES == 1 (VPL by VPL), in fewer loop trips than
  // the N^2 the dispatch is sized for.
  int samples = samplesOfPixel(pixel);
#endif
  for (uint k = 0u; k < uVplCount; ++k) {
    ++iterations;
    Vpl vpl = vpls[uFirstVpl + k];
#if PIXEL_SAMPLES == 1
    gatherVpl(local, at, k, vpl, lostBefore, lostAfter, iterations);
#else
    // Samples re-read per VPL: a VPL-major order keeps the bytes independent
    // of the dispatch split, and the G-buffer reads are cheap next to a VPL.
    for (int s = 0; s < samples; ++s) {
      ++iterations;
      Sample at = loadSample(xy, samples, s);
      if (at.lit) gatherVpl(local, at, k, vpl, lostBefore, lostAfter, iterations);
    }
#endif
  }
#ifdef PIXEL_FOOTPRINT
  outside[2u * local] = lostBefore;
  outside[2u * local + 1u] = lostAfter;
#else
  outside[2u * local] += lostBefore;
  outside[2u * local + 1u] += lostAfter;
#endif
  if (iterations >= kLoopTripLimit) atomicOr(loopLimitHit, 1u);
}
