#version 450 core
// Surface attributes of the first surface seen from a viewpoint (the camera,
// or the light for the reflective shadow map). Surfaces are two-sided: the
// normal is turned to face the viewpoint.
in vec3 vPosition_world;
in vec3 vNormal_world;
in vec2 vUv;

uniform vec3 uViewpoint_world;
uniform vec3 uAlbedoFactor;
uniform int uHasAlbedoTexture;
layout(binding = TOFSIM_UNIT_ALBEDO_TEXTURE) uniform sampler2D uAlbedoTexture;
#ifdef GLTF_MATERIALS
// render.materials: gltf. metallic = factor.x * texture.b, roughness = factor.y * texture.g.
uniform vec2 uMetallicRoughnessFactor;
uniform int uHasMetallicRoughnessTexture;
layout(binding = TOFSIM_UNIT_METALLIC_ROUGHNESS_TEXTURE) uniform sampler2D uMetallicRoughnessTexture;
layout(location = TOFSIM_OUT_METALLIC_ROUGHNESS) out vec2 outMetallicRoughness;
#endif

layout(location = TOFSIM_OUT_POSITION) out vec4 outPosition;  // xyz world, w = 1 where a surface was hit
layout(location = TOFSIM_OUT_NORMAL) out vec4 outNormal;    // xyz unit world normal facing the viewpoint
layout(location = TOFSIM_OUT_ALBEDO) out vec4 outAlbedo;    // rgb diffuse albedo

void main() {
  vec3 n = normalize(vNormal_world);
  if (dot(n, uViewpoint_world - vPosition_world) < 0.0) n = -n;
  vec3 albedo = uAlbedoFactor;
  if (uHasAlbedoTexture != 0) albedo *= texture(uAlbedoTexture, vUv).rgb;
  outPosition = vec4(vPosition_world, 1.0);
  outNormal = vec4(n, 0.0);
  outAlbedo = vec4(albedo, 1.0);
#ifdef GLTF_MATERIALS
  vec2 metallicRoughness = uMetallicRoughnessFactor;
  if (uHasMetallicRoughnessTexture != 0) {
    metallicRoughness *= texture(uMetallicRoughnessTexture, vUv).bg;
  }
  outMetallicRoughness = metallicRoughness;
#endif
}
