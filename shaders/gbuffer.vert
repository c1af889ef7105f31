#version 450 core
// Transforms world-space vertices; shared by the camera G-buffer, the light's
// shadow map and the reflective shadow map passes.
layout(location = TOFSIM_ATTRIB_POSITION) in vec3 inPosition_world;
layout(location = TOFSIM_ATTRIB_NORMAL) in vec3 inNormal_world;
layout(location = TOFSIM_ATTRIB_UV) in vec2 inUv;

uniform mat4 uViewProjection;

out vec3 vPosition_world;
out vec3 vNormal_world;
out vec2 vUv;

void main() {
  vPosition_world = inPosition_world;
  vNormal_world = inNormal_world;
  vUv = inUv;
  gl_Position = uViewProjection * vec4(inPosition_world, 1.0);
}
