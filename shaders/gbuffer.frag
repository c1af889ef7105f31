#version 450 core
// Surface attributes of the first surface seen from a viewpoint (the camera,
// or the light for the reflective shadow map). Surfaces are two-sided: the
// normal is turned to face the viewpoint.
in vec3 vPosition_world;
in vec3 vNormal_world;
in vec2 vUv;

uniform vec3 uViewpoint_world;
// The mesh's material: its index into the scene's vertex table
// (ir::materialVertices; the gathers' uScatterVertices), and its textures,
// whose texels multiply the vertex's factors (physics::texturedVertex).
uniform int uMaterial;
uniform int uHasAlbedoTexture;
layout(binding = TOFSIM_UNIT_ALBEDO_TEXTURE) uniform sampler2D uAlbedoTexture;
#ifdef GLTF_MATERIALS
// render.materials: gltf: the metallic-roughness texture's (b, g).
uniform int uHasMetallicRoughnessTexture;
layout(binding = TOFSIM_UNIT_METALLIC_ROUGHNESS_TEXTURE) uniform sampler2D uMetallicRoughnessTexture;
layout(location = TOFSIM_OUT_METALLIC_ROUGHNESS) out vec2 outMetallicRoughness;
#endif

layout(location = TOFSIM_OUT_POSITION) out vec4 outPosition;  // xyz world, w = 1 where a surface was hit
layout(location = TOFSIM_OUT_NORMAL) out vec4 outNormal;    // xyz unit world normal facing the viewpoint
layout(location = TOFSIM_OUT_ALBEDO) out vec4 outAlbedo;    // rgb base-colour texel (1: none), a material index

void main() {
  vec3 n = normalize(vNormal_world);
  if (dot(n, uViewpoint_world - vPosition_world) < 0.0) n = -n;
  vec3 baseColor = vec3(1.0);
  if (uHasAlbedoTexture != 0) baseColor = texture(uAlbedoTexture, vUv).rgb;
  outPosition = vec4(vPosition_world, 1.0);
  outNormal = vec4(n, 0.0);
  outAlbedo = vec4(baseColor, float(uMaterial));
#ifdef GLTF_MATERIALS
  vec2 metallicRoughness = vec2(1.0);
  if (uHasMetallicRoughnessTexture != 0) {
    metallicRoughness = texture(uMetallicRoughnessTexture, vUv).bg;
  }
  outMetallicRoughness = metallicRoughness;
#endif
}
