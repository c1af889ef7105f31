// The scene as a triangle soup in BVH order (TriangleSoup.cpp): uniform
// sampling by area and any-hit occlusion along a segment.
#include "transient_physics.glsl"
layout(std430, binding = TOFSIM_SSBO_CORNERS) readonly buffer Corners { vec4 corners[]; };
layout(std430, binding = TOFSIM_SSBO_AREA_CDF) readonly buffer AreaCdf { float areaCdf[]; };
struct BvhNode { vec4 lo; vec4 hi; };
layout(std430, binding = TOFSIM_SSBO_BVH) readonly buffer Bvh { BvhNode bvh[]; };

uniform uint uTriangleCount;

// Point on the scene's surface for three uniform numbers; one triangle is
// chosen with probability proportional to its area.
vec3 sampleSurface(float r0, float r1, float r2) {
  uint lo = 0u, hi = uTriangleCount - 1u;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (areaCdf[mid] > r0) hi = mid; else lo = mid + 1u;
  }
  return pointOnTriangle(corners[3u * lo].xyz, corners[3u * lo + 1u].xyz, corners[3u * lo + 2u].xyz,
                         r1, r2);
}

bool hitsBox(vec3 lo, vec3 hi, vec3 origin, vec3 invDir, float tMax) {
  vec3 t0 = (lo - origin) * invDir, t1 = (hi - origin) * invDir;
  vec3 tNear = min(t0, t1), tFar = max(t0, t1);
  float enter = max(max(tNear.x, tNear.y), max(tNear.z, 0.0));
  float exit = min(min(tFar.x, tFar.y), min(tFar.z, tMax));
  return enter <= exit;
}

// Moller-Trumbore; t is the fraction of the segment origin -> origin + dir.
bool hitsTriangle(uint tri, vec3 origin, vec3 dir, float tMin, float tMax) {
  vec3 a = corners[3u * tri].xyz;
  vec3 e1 = corners[3u * tri + 1u].xyz - a, e2 = corners[3u * tri + 2u].xyz - a;
  vec3 p = cross(dir, e2);
  float det = dot(e1, p);
  if (abs(det) < 1e-20) return false;
  float inv = 1.0 / det;
  vec3 s = origin - a;
  float u = dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return false;
  vec3 q = cross(s, e1);
  float v = dot(dir, q) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  float t = dot(e2, q) * inv;
  return t > tMin && t < tMax;
}

// True when a triangle blocks the open segment from -> to (its ends excluded
// by a small relative margin so the surfaces at either end do not count).
// `iterations` counts loop trips (see kLoopTripLimit in indirect_gather.comp).
bool segmentOccluded(vec3 from, vec3 to, inout uint iterations) {
  vec3 dir = to - from;
  vec3 invDir = 1.0 / dir;
  const float margin = 1e-4;
  uint stack[48];
  int top = 0;
  uint node = 0u;
  while (true) {
    ++iterations;
    BvhNode n = bvh[node];
    if (hitsBox(n.lo.xyz, n.hi.xyz, from, invDir, 1.0)) {
      uint count = floatBitsToUint(n.hi.w);
      if (count > 0u) {
        uint first = floatBitsToUint(n.lo.w);
        for (uint i = first; i < first + count; ++i) {
          ++iterations;
          if (hitsTriangle(i, from, dir, margin, 1.0 - margin)) return true;
        }
      } else {
        stack[top++] = floatBitsToUint(n.lo.w);  // right child
        node = node + 1u;                         // left child follows its parent
        continue;
      }
    }
    if (top == 0) return false;
    node = stack[--top];
  }
}
