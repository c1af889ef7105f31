#version 450 core
// Direct transient light: one thread per pixel of the segment. The pixel's
// surface point x receives the light's impulse after |l - x| and reflects it
// (Lambertian) to the camera after |x - c|; the radiance lands in the bin of
// the full optical path eta * (|l - x| + |x - c|), or eta * |l - x| when the
// camera delay is unwarped. Each bin has this thread as its only writer, so
// the result does not depend on scheduling.
layout(local_size_x = TOFSIM_WORK_GROUP_SIZE) in;

#include "light.glsl"

layout(binding = TOFSIM_UNIT_G_POSITION) uniform sampler2D uGPosition;
layout(binding = TOFSIM_UNIT_G_NORMAL) uniform sampler2D uGNormal;
layout(binding = TOFSIM_UNIT_G_ALBEDO) uniform sampler2D uGAlbedo;

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
uniform vec3 uCameraPosition_world;

void main() {
  uint local = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
  if (local >= uPixelCount) return;
  uint pixel = uFirstPixel + local;
  ivec2 xy = ivec2(int(pixel % uint(uImageWidth)), int(pixel / uint(uImageWidth)));
  vec4 position = texelFetch(uGPosition, xy, 0);
  if (position.w == 0.0) return;
  vec3 x = position.xyz;
  vec3 n = texelFetch(uGNormal, xy, 0).xyz;
  vec3 albedo = texelFetch(uGAlbedo, xy, 0).rgb;

  vec3 toLight = uLightPosition_world - x;
  float dLight = length(toLight);
  vec3 wLight = toLight / dLight;
  float cosX = dot(n, wLight);
  if (cosX <= 0.0) return;
  float profile = spotProfile(-wLight);
  if (profile <= 0.0 || !visibleFromLight(x, cosX)) return;

  vec3 radiance = lambertianDirect(albedo, uLightIntensity_W_per_sr, profile, cosX, dLight);
  float dCamera = uCameraUnwarp != 0 ? 0.0 : length(x - uCameraPosition_world);
  float path_m = directPathLength(uIndexOfRefraction, dLight, dCamera);
  int bin = binOfPath(path_m, uStart_m, uBinWidth_m);
  if (bin < 0 || bin >= uBins) {
    outside[2u * local + (bin < 0 ? 0u : 1u)] += radiance.r + radiance.g + radiance.b;
    return;
  }
  uint base = (local * uint(uBins) + uint(bin)) * uint(TOFSIM_CHANNELS);
  direct[base + 0u] = radiance.r;
  direct[base + 1u] = radiance.g;
  direct[base + 2u] = radiance.b;
}
