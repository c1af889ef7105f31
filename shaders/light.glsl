// The point, spot or Lambertian light and its shadow map (a cube rendered as
// six layers of a 2D array texture). How it reaches a surface point is
// lightArrival in transient_physics.glsl, which the CPU backend calls too;
// the uniforms are capture::Light::profileTerms (LightUniforms.cpp).
#include "transient_physics.glsl"

uniform vec3 uLightPosition_world;
uniform vec3 uLightDirection_world;
uniform vec3 uLightIntensity_W_per_sr;
uniform int uLightProfile;  // LIGHT_POINT, LIGHT_SPOT or LIGHT_LAMBERTIAN (transient_physics.glsl)
uniform float uSpotCosOuter;
uniform float uSpotCosInner;

uniform mat4 uShadowViewProjection[6];
uniform int uShadowResolution;
layout(binding = TOFSIM_UNIT_SHADOW_MAP) uniform sampler2DArray uShadowMap;

// transient_physics.glsl's lightArrival for this light.
LightArrival arrivalAt(ScatterVertex v, vec3 x, vec3 n) {
  return vertexLightArrival(v, x, n, uLightPosition_world, uLightProfile, uLightDirection_world,
                            uSpotCosOuter, uSpotCosInner);
}

int cubeFace(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x > 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y > 0.0 ? 2 : 3;
  return d.z > 0.0 ? 4 : 5;
}

// True when nothing lies between the light and x. cosAtX is the cosine between
// the surface normal at x and the direction to the light: grazing surfaces
// need a larger bias because one texel spans a longer stretch of depth there.
bool visibleFromLight(vec3 x, float cosAtX) {
  vec3 d = x - uLightPosition_world;
  int face = cubeFace(d);
  vec4 clip = uShadowViewProjection[face] * vec4(x, 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  ivec2 texel = clamp(ivec2(uv * float(uShadowResolution)), ivec2(0), ivec2(uShadowResolution - 1));
  float stored = texelFetch(uShadowMap, ivec3(texel, face), 0).r;
  float dist = length(d);
  float texelSize = 2.0 * dist / float(uShadowResolution);
  float tanAngle = sqrt(max(1.0 - cosAtX * cosAtX, 0.0)) / max(cosAtX, 0.05);
  float bias = texelSize * (1.5 + 2.0 * tanAngle) + 1e-5 * dist;
  return dist - bias <= stored;
}
