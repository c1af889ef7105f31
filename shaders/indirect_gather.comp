#version 450 core
// One indirect bounce (Eqs. 6, 7, 15, 17): one thread per pixel loops over the
// batch's VPLs in index order and adds each contribution to the bin of its
// full optical path  t_l + eta (|x_l - x| + |x - c|). Being the only writer of
// its pixel's bins, and adding in a fixed order, makes the sum reproducible
// bit for bit whatever the batch and segment sizes.
layout(local_size_x = TOFSIM_WORK_GROUP_SIZE) in;

#include "transient_physics.glsl"
#include "vpl.glsl"
#ifdef EXACT_VISIBILITY
#include "scene_geometry.glsl"
#else
layout(std430, binding = TOFSIM_SSBO_ISM) readonly buffer Ism { float ism[]; };
uniform uint uVplStride;
uniform int uIsmResolution;
#endif

layout(binding = TOFSIM_UNIT_G_POSITION) uniform sampler2D uGPosition;
layout(binding = TOFSIM_UNIT_G_NORMAL) uniform sampler2D uGNormal;
layout(binding = TOFSIM_UNIT_G_ALBEDO) uniform sampler2D uGAlbedo;

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
uniform vec3 uCameraPosition_world;
uniform uint uFirstVpl;     // first VPL of this dispatch
uniform uint uVplCount;     // VPLs in this dispatch
uniform uint uIsmFirstVpl;  // first VPL whose ISM is at the start of the ISM buffer
uniform float uGeometryClamp;  // <= 0: no clamping
uniform float uSceneScale_m;

// llvmpipe stops every loop of an invocation after 65535 iterations in total
// (its infinite-loop guard), silently, and counts loop entries too. The
// renderer sizes dispatches to stay well below; an invocation that still
// comes within a factor of two raises this flag so the render fails loudly
// instead of losing light.
const uint kLoopTripLimit = 30000u;
layout(std430, binding = TOFSIM_SSBO_LOOP_GUARD) buffer LoopGuard { uint loopLimitHit; };

bool visible(uint ismIndex, Vpl vpl, vec3 x, vec3 n, vec3 d, float dist, inout uint iterations) {
#ifdef EXACT_VISIBILITY
  float eps = 1e-4 * uSceneScale_m;
  return !segmentOccluded(vpl.positionPath.xyz + vpl.normal.xyz * eps, x + n * eps, iterations);
#else
  ivec2 texel = paraboloidTexel(vpl, d, uIsmResolution);
  float stored = ism[ismIndex * uVplStride + uint(texel.y * uIsmResolution + texel.x)];
  // One texel spans about 4/R radians; points are a sparse sample of the
  // surfaces, so the bias grows with distance.
  float bias = dist * (4.0 / float(uIsmResolution)) + 0.01 * uSceneScale_m;
  return dist - bias <= stored;
#endif
}

void main() {
  uint local = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
  if (local >= uPixelCount) return;
  uint pixel = uFirstPixel + local;
  ivec2 xy = ivec2(int(pixel % uint(uImageWidth)), int(pixel / uint(uImageWidth)));
  vec4 position = texelFetch(uGPosition, xy, 0);
  if (position.w == 0.0) return;
  vec3 x = position.xyz;
  vec3 n = texelFetch(uGNormal, xy, 0).xyz;
  vec3 brdf = texelFetch(uGAlbedo, xy, 0).rgb / PI;
  float cameraPath =
      cameraPathLength(uCameraUnwarp != 0, uIndexOfRefraction, length(x - uCameraPosition_world));
  uint base = local * uint(uBins);
  float lostBefore = 0.0;
  float lostAfter = 0.0;
  uint iterations = 0u;
  for (uint k = 0u; k < uVplCount; ++k) {
    ++iterations;
    Vpl vpl = vpls[uFirstVpl + k];
    vec3 toX = x - vpl.positionPath.xyz;
    float dist2 = dot(toX, toX);
    if (dist2 <= 0.0) continue;
    float dist = sqrt(dist2);
    vec3 d = toX / dist;
    float cosVpl = dot(vpl.normal.xyz, d);
    float cosX = -dot(n, d);
    if (cosVpl <= 0.0 || cosX <= 0.0) continue;
    float g = geometryTerm(cosVpl, cosX, dist2, uGeometryClamp);
    if (!visible(uFirstVpl - uIsmFirstVpl + k, vpl, x, n, d, dist, iterations)) continue;
    vec3 radiance = brdf * vpl.flux.rgb * g;
    float path_m = vplPathLength(vpl.positionPath.w, uIndexOfRefraction, dist, cameraPath);
    int bin = binOfPath(path_m, uStart_m, uBinWidth_m);
    if (bin < 0 || bin >= uBins) {
      float value = radiance.r + radiance.g + radiance.b;
      if (bin < 0) {
        lostBefore += value;
      } else {
        lostAfter += value;
      }
      continue;
    }
    uint i = (base + uint(bin)) * uint(TOFSIM_CHANNELS);
    indirect[i + 0u] += radiance.r;
    indirect[i + 1u] += radiance.g;
    indirect[i + 2u] += radiance.b;
  }
  outside[2u * local] += lostBefore;
  outside[2u * local + 1u] += lostAfter;
  if (iterations >= kLoopTripLimit) atomicOr(loopLimitHit, 1u);
}
