// A VPL's light near its own patch, written once in the common subset of
// GLSL 4.50 and C++/GLM (the rules of transient_physics.glsl): the indirect
// gather includes this file, C++ through
// core/physics/include/tofsim/physics/VplNearField.h.
//
// A VPL stands for its RSM texel's patch, a parallelogram of area A on the
// surface, and lights a point x with cos_l cos_x A / d^2: the patch's
// integral by its midpoint. Where x lies within a few patch widths (at a
// crease, where the VPL's wall meets x's floor) that term has no bound: a
// sample next to a VPL gets 1/d^2 (the spikes of an unclamped render), and
// a geometry clamp cuts them at the price of the crease's light. There the
// gather takes the patch's integral itself instead,
//   integral over the patch of cos_l cos_x / d^2 dA = the patch's projected
//   solid angle seen from x (Lambert's formula over its edges),
// divided by A: the same light, spread uniformly over the patch as the VPL's
// flux is, exact at any distance and at most pi / A. Far from the patch the
// two agree (NEAR_FIELD_WIDTHS: to 0.5 % where the switch happens), so only
// the pairs that need it pay for the edges.
#ifndef TOFSIM_VPL_NEAR_FIELD_GLSL
#define TOFSIM_VPL_NEAR_FIELD_GLSL

#ifndef TOFSIM_PHYSICS_FN
#define TOFSIM_PHYSICS_FN
#endif

// Within this many patch widths (sqrt(A)) the patch's integral replaces the
// point VPL's term. The midpoint rule's relative error for a square seen
// head-on at distance d is about A / (3 d^2): 0.5 % at 8 widths.
const float NEAR_FIELD_WIDTHS = 8.0f;

// The squared squared radius of a VPL's near field, NEAR_FIELD_WIDTHS^4 A^2
// (m^4), from its patch steps patchU, patchV (m; zero for a point VPL: a
// later bounce's, which then has none). One value per VPL: the CPU gather
// holds it in an array (VplArrays::nearLimit) instead of a cross product
// per pair.
TOFSIM_PHYSICS_FN float vplNearFieldLimit(vec3 patchU, vec3 patchV) {
  vec3 normalArea = cross(patchU, patchV);
  float area2 = dot(normalArea, normalArea);
  float widths2 = NEAR_FIELD_WIDTHS * NEAR_FIELD_WIDTHS;
  return widths2 * widths2 * area2;
}

// Whether x at squared distance dist2 from a VPL whose vplNearFieldLimit is
// `limit` lies in its near field: dist2 < NEAR_FIELD_WIDTHS^2 A, compared
// squared, without a square root (never for a point VPL: limit 0).
TOFSIM_PHYSICS_FN bool vplInNearField(float dist2, float limit) {
  return dist2 * dist2 < limit;
}

// The angle between two vectors from |a x b| = sine >= 0 and a . b = cosine:
// atan2(sine, cosine) in [0, pi] by Cephes' atanf (range reduction to
// |t| <= tan(pi / 8), then an odd polynomial of degree 9; within 3e-7 rad
// of atan2, tests/physics/VplNearFieldTest.cpp). Written here rather than
// taken from each platform's atan: a quarter of a low-resolution RSM's
// indirect gather was libm's atan2f, and GL and CPU now evaluate the same
// operations.
TOFSIM_PHYSICS_FN float edgeAngle(float sine, float cosine) {
  if (cosine == 0.0f) return 1.5707963267948966f;
  float t = sine / abs(cosine);  // >= 0
  float base = 0.0f;
  if (t > 2.414213562373095f) {
    base = 1.5707963267948966f;
    t = -1.0f / t;
  } else if (t > 0.4142135623730950f) {
    base = 0.7853981633974483f;
    t = (t - 1.0f) / (t + 1.0f);
  }
  float z = t * t;
  float angle = base + ((((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z -
                         3.33329491539e-1f) * z * t + t);
  return cosine > 0.0f ? angle : 3.1415926535897932f - angle;
}

// The corners of the parallelogram centre +- patchU / 2 +- patchV / 2,
// relative to x, in order around it. A struct: GLSL and C++ both return it.
struct PatchCorners {
  vec3 c0;
  vec3 c1;
  vec3 c2;
  vec3 c3;
};

TOFSIM_PHYSICS_FN PatchCorners patchCornersFrom(vec3 x, vec3 centre, vec3 patchU, vec3 patchV) {
  PatchCorners q;
  q.c0 = centre - 0.5f * patchU - 0.5f * patchV - x;
  q.c1 = centre + 0.5f * patchU - 0.5f * patchV - x;
  q.c2 = centre + 0.5f * patchU + 0.5f * patchV - x;
  q.c3 = centre - 0.5f * patchU + 0.5f * patchV - x;
  return q;
}

// Edge a -> b of a polygon seen from the origin (a, b relative to x) in
// Lambert's formula: the angle it subtends times the cosine between n and
// its plane; 0 for an edge through x.
TOFSIM_PHYSICS_FN float lambertEdge(vec3 a, vec3 b, vec3 n) {
  vec3 edgePlane = cross(a, b);
  float sine = length(edgePlane);  // |a| |b| sin(angle)
  return sine > 0.0f ? edgeAngle(sine, dot(a, b)) * (dot(n, edgePlane) / sine) : 0.0f;
}

// Whether no corner lies below x's tangent plane (normal n): the quad needs
// no clip, and its edges' sum is lambertEdge over c0 c1, c1 c2, c2 c3, c3 c0
// in that order (the CPU gather evaluates such lanes eight at a time).
TOFSIM_PHYSICS_FN bool patchAboveHorizon(PatchCorners q, vec3 n) {
  return dot(q.c0, n) >= 0.0f && dot(q.c1, n) >= 0.0f && dot(q.c2, n) >= 0.0f &&
         dot(q.c3, n) >= 0.0f;
}

TOFSIM_PHYSICS_FN float unclippedEdgeSum(PatchCorners q, vec3 n) {
  float sum = 0.0f;
  sum += lambertEdge(q.c0, q.c1, n);
  sum += lambertEdge(q.c1, q.c2, n);
  sum += lambertEdge(q.c2, q.c3, n);
  sum += lambertEdge(q.c3, q.c0, n);
  return sum;
}

// Projected solid angle (sr) of the parallelogram centre +- patchU / 2 +-
// patchV / 2 seen from x with unit normal n: the part above x's tangent
// plane (the quad clipped against it: at most five corners), by Lambert's
// formula, half the sum over its edges of the angle each subtends times the
// cosine between n and the edge's plane.
TOFSIM_PHYSICS_FN float patchProjectedSolidAngle(vec3 x, vec3 n, vec3 centre, vec3 patchU,
                                                 vec3 patchV) {
  PatchCorners q = patchCornersFrom(x, centre, patchU, patchV);
  if (patchAboveHorizon(q, n)) return 0.5f * abs(unclippedEdgeSum(q, n));
  vec3 corner[4];
  corner[0] = q.c0;
  corner[1] = q.c1;
  corner[2] = q.c2;
  corner[3] = q.c3;
  vec3 polygon[5];
  int count = 0;
  for (int i = 0; i < 4; ++i) {
    vec3 a = corner[i];
    vec3 b = corner[(i + 1) % 4];
    float ha = dot(a, n);
    float hb = dot(b, n);
    if (ha >= 0.0f) {
      polygon[count] = a;
      count += 1;
    }
    if ((ha >= 0.0f) != (hb >= 0.0f)) {
      polygon[count] = a + (b - a) * (ha / (ha - hb));
      count += 1;
    }
  }
  float sum = 0.0f;
  for (int i = 0; i < count; ++i) sum += lambertEdge(polygon[i], polygon[(i + 1) % count], n);
  return 0.5f * abs(sum);
}

// The geometry term of a VPL at vplX with patch steps patchU, patchV for the
// point x with unit normal n (cosVpl, cosX, dist2 and clampPerM2 as
// geometryTerm takes them): in the near field the patch's projected solid
// angle over its area, unclamped (it is bounded); else the point VPL's
// clamped cos cos / d^2. A patch across x's horizon is a texel whose light
// fell on two surfaces (the RSM gave it all to the one at its centre): the
// part below the horizon stands for light that reached x's own surface, and
// the clip drops it, continuously as the patch moves (no switch between two
// estimates: the same on every backend, smooth over time).
TOFSIM_PHYSICS_FN float vplGeometryTerm(float cosVpl, float cosX, float dist2, float clampPerM2,
                                        vec3 x, vec3 n, vec3 vplX, vec3 patchU, vec3 patchV) {
  if (!vplInNearField(dist2, vplNearFieldLimit(patchU, patchV))) {
    return geometryTerm(cosVpl, cosX, dist2, clampPerM2);
  }
  return patchProjectedSolidAngle(x, n, vplX, patchU, patchV) / length(cross(patchU, patchV));
}

// A medium point x (no normal: it takes light from every direction, its
// phase function in scatter()) weighs the patch's light by
//   integral over the patch of cos_l / d^2 dA = the patch's solid angle seen
//   from x,
// the same patch integral as above without x's cosine: at most 2 pi / A (x
// on the patch's plane, inside it), where the point VPL's cos_l / d^2 has no
// bound. The solid angle of triangle (a, b, c), corners relative to x, by
// Van Oosterom and Strackee's formula:
//   tan(omega / 2) = |a . (b x c)| / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|),
// with edgeAngle for atan2 (the denominator may be negative: omega > pi).
TOFSIM_PHYSICS_FN float triangleSolidAngle(vec3 a, vec3 b, vec3 c) {
  float la = length(a);
  float lb = length(b);
  float lc = length(c);
  float numerator = abs(dot(a, cross(b, c)));
  float denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  return 2.0f * edgeAngle(numerator, denominator);
}

// Solid angle (sr) of the parallelogram centre +- patchU / 2 +- patchV / 2
// seen from x: its two triangles c0 c1 c2 and c0 c2 c3.
TOFSIM_PHYSICS_FN float patchSolidAngle(vec3 x, vec3 centre, vec3 patchU, vec3 patchV) {
  PatchCorners q = patchCornersFrom(x, centre, patchU, patchV);
  return triangleSolidAngle(q.c0, q.c1, q.c2) + triangleSolidAngle(q.c0, q.c2, q.c3);
}

// vplGeometryTerm for a medium point x (receiver cosine 1, receiverCosine):
// in the near field the patch's solid angle over its area, unclamped (it is
// bounded); else the point VPL's clamped cos_l / d^2. Only a lit pair asks
// (cosVpl > 0): x then sees the patch's lit face, all of it (a plane).
TOFSIM_PHYSICS_FN float vplMediumGeometryTerm(float cosVpl, float dist2, float clampPerM2, vec3 x,
                                              vec3 vplX, vec3 patchU, vec3 patchV) {
  if (!vplInNearField(dist2, vplNearFieldLimit(patchU, patchV))) {
    return geometryTerm(cosVpl, 1.0f, dist2, clampPerM2);
  }
  return patchSolidAngle(x, vplX, patchU, patchV) / length(cross(patchU, patchV));
}

#endif  // TOFSIM_VPL_NEAR_FIELD_GLSL
