// Virtual point lights from the reflective shadow map (Vpls.cpp) and the
// paraboloid parametrisation of their imperfect shadow maps.
struct Vpl {
  vec4 positionPath;  // xyz world position; w = optical path light -> VPL, metres
  vec4 normal;        // xyz unit normal on the lit side
  vec4 flux;          // rgb: albedo * flux / pi, W/sr (cosine-weighted intensity)
};
layout(std430, binding = TOFSIM_SSBO_VPLS) readonly buffer Vpls { Vpl vpls[]; };

// Orthonormal basis around n (Duff et al. 2017), identical wherever used.
mat3 basisAround(vec3 n) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float b = n.x * n.y * a;
  vec3 t = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
  vec3 bt = vec3(b, s + n.y * n.y * a, -n.y);
  return mat3(t, bt, n);
}

// Texel of direction d (unit, world) in the VPL's hemisphere map; d must lie
// on the side of the normal.
ivec2 paraboloidTexel(Vpl vpl, vec3 d, int resolution) {
  vec3 local = transpose(basisAround(vpl.normal.xyz)) * d;
  vec2 uv = local.xy / (1.0 + max(local.z, 0.0)) * 0.5 + 0.5;
  return clamp(ivec2(uv * float(resolution)), ivec2(0), ivec2(resolution - 1));
}
