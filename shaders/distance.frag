#version 450 core
// Distance from the light to the nearest surface, for the light's shadow map.
in vec3 vPosition_world;
in vec3 vNormal_world;
in vec2 vUv;

uniform vec3 uViewpoint_world;

layout(location = TOFSIM_OUT_POSITION) out float outDistance_m;

void main() { outDistance_m = length(vPosition_world - uViewpoint_world); }
