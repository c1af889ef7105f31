#pragma once
// Private to core/rays, included only by the per-instruction-set kernel
// files (BundleKernelAvx512.cpp, BundleKernelAvx2.cpp), each of which
// defines the lane type L first: Embree 3.13.5's robust ray/triangle test
// (kernels/geometry/triangle_intersector_pluecker.h, PlueckerIntersector1
// and PlueckerHitM::finalize), written once for a bundle's rays.
//
// Embree tests one ray against 4 triangles per vector; here one triangle
// against L::W rays per vector. Each lane's arithmetic is the same either
// way: the same operations (explicit fused multiply-adds where Embree's
// madd / msub are, none where it has none: the kernels are compiled with
// -ffp-contract=off), the same reciprocal (the instruction Embree's vfloat4
// rcp uses for that instruction set, and its Newton step), so t, U, V and
// the barycentrics are Embree's to the bit. What depends on the triangle
// and the shared origin alone (edges, crosses, the normal, T) is computed
// once per triangle, in scalar fused multiply-adds: the same roundings.

#include <cfloat>

#include "BundleLanes.h"

namespace tofsim::rays::detail {
// Internal linkage throughout: each kernel file's copy is compiled for its
// own instruction set, and no linker may pick one for the other.
namespace {
namespace pluecker {

struct Vec {
  float x, y, z;
};
inline Vec sub(const Vec& a, const Vec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec add(const Vec& a, const Vec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
// Embree's msub(a, b, c) = a * b - c, fused.
inline float msub(float a, float b, float c) { return __builtin_fmaf(a, b, -c); }
// Embree's cross: msub(a.y, b.z, a.z * b.y), ...
inline Vec cross(const Vec& a, const Vec& b) {
  return {msub(a.y, b.z, a.z * b.y), msub(a.z, b.x, a.x * b.z), msub(a.x, b.y, a.y * b.x)};
}
// Embree's dot: madd(a.x, b.x, madd(a.y, b.y, a.z * b.z)).
inline float dot(const Vec& a, const Vec& b) {
  return __builtin_fmaf(a.x, b.x, __builtin_fmaf(a.y, b.y, a.z * b.z));
}
inline float absf(float x) { return __builtin_fabsf(x); }
inline float norm1(const Vec& a) { return absf(a.x) + absf(a.y) + absf(a.z); }
constexpr float kEdgeBand = 1e-5f;
// Embree's stable_triangle_normal(a, b, c).
inline Vec stableNormal(const Vec& a, const Vec& b, const Vec& c) {
  const float abx = a.z * b.y, aby = a.x * b.z, abz = a.y * b.x;
  const float bcx = b.z * c.y, bcy = b.x * c.z, bcz = b.y * c.x;
  const Vec crossAb{msub(a.y, b.z, abx), msub(a.z, b.x, aby), msub(a.x, b.y, abz)};
  const Vec crossBc{msub(b.y, c.z, bcx), msub(b.z, c.x, bcy), msub(b.x, c.y, bcz)};
  return {absf(abx) < absf(bcx) ? crossAb.x : crossBc.x,
          absf(aby) < absf(bcy) ? crossAb.y : crossBc.y,
          absf(abz) < absf(bcz) ? crossAb.z : crossBc.z};
}

// Lanes: dot(a, D) with a broadcast, as Embree's dot(a, D).
template <class L>
inline typename L::F dotLanes(const Vec& a, typename L::F dx, typename L::F dy, typename L::F dz) {
  return L::fma(L::set(a.x), dx, L::fma(L::set(a.y), dy, L::mul(L::set(a.z), dz)));
}

}  // namespace pluecker

template <class L>
void intersectLanes(BundleRays& rays, const BundleTriangle* triangles, const int32_t* indices,
                    int count) {
  using namespace pluecker;
  using F = typename L::F;
  using M = typename L::M;
  const Vec origin{rays.ox, rays.oy, rays.oz};
  for (int k = 0; k < count; ++k) {
    const BundleTriangle& tri = triangles[indices[k]];
    // Vertices relative to the ray origin, edges, edge planes (crosses).
    const Vec v0 = sub(Vec{tri.v0[0], tri.v0[1], tri.v0[2]}, origin);
    const Vec v1 = sub(Vec{tri.v1[0], tri.v1[1], tri.v1[2]}, origin);
    const Vec v2 = sub(Vec{tri.v2[0], tri.v2[1], tri.v2[2]}, origin);
    const Vec e0 = sub(v2, v0), e1 = sub(v0, v1), e2 = sub(v1, v2);
    const Vec c0 = cross(e0, add(v2, v0)), c1 = cross(e1, add(v0, v1)), c2 = cross(e2, add(v1, v2));
    const Vec ng = stableNormal(e0, e1, e2);
    const float dotT = dot(v0, ng);
    // Within how much of 0 U, V and W are uncertain (kEdgeBand of the size
    // of their terms, some 80 float roundings): a ray that close to an edge
    // may be one Embree's traversal never brings to this triangle (its boxes
    // end at the edge, and the ray passes just outside), so its hit is
    // flagged for Embree (edgeT).
    const F bandU = L::set(kEdgeBand * norm1(e0) * norm1(add(v2, v0)));
    const F bandV = L::set(kEdgeBand * norm1(e1) * norm1(add(v0, v1)));
    const F bandW = L::set(kEdgeBand * norm1(e2) * norm1(add(v1, v2)));
    const F T = L::set(dotT + dotT);  // twice(dot(v0, Ng))
    for (int g = 0; g < kBundleLanes; g += L::W) {
      const F dx = L::load(rays.dx + g), dy = L::load(rays.dy + g), dz = L::load(rays.dz + g);
      const F U = dotLanes<L>(c0, dx, dy, dz);
      const F V = dotLanes<L>(c1, dx, dy, dz);
      const F W = dotLanes<L>(c2, dx, dy, dz);
      const F UVW = L::add(L::add(U, V), W);
      const F eps = L::mul(L::set(FLT_EPSILON), L::abs(UVW));
      M valid = L::andm(
          L::loadMask(rays.active + g),
          L::orm(L::ge(L::min(L::min(U, V), W), L::neg(eps)), L::le(L::max(L::max(U, V), W), eps)));
      if (!L::any(valid)) continue;
      const F d = dotLanes<L>(ng, dx, dy, dz);
      const F den = L::add(d, d);  // twice(dot(Ng, D))
      const F t = L::mul(L::rcp(den), T);
      const F best = L::load(rays.t + g);
      valid = L::andm(valid, L::andm(L::andm(L::le(L::set(0.0f), t), L::le(t, best)),
                                     L::neq(den, L::set(0.0f))));
      if (!L::any(valid)) continue;
      const M closer = L::andm(valid, L::lt(t, best));
      const M same = L::andm(L::andm(valid, L::eq(t, best)), L::loadHitMask(rays.hit + g));
      const M edge = L::andm(valid, L::orm(L::orm(L::lt(L::abs(U), bandU), L::lt(L::abs(V), bandV)),
                                           L::lt(L::abs(W), bandW)));
      L::store(rays.edgeT + g,
               L::blend(edge, L::min(t, L::load(rays.edgeT + g)), L::load(rays.edgeT + g)));
      L::store(rays.t + g, L::blend(closer, t, best));
      L::store(rays.U + g, L::blend(closer, U, L::load(rays.U + g)));
      L::store(rays.V + g, L::blend(closer, V, L::load(rays.V + g)));
      L::store(rays.UVW + g, L::blend(closer, UVW, L::load(rays.UVW + g)));
      L::storeHit(rays.hit + g, closer, indices[k]);
      L::storeTie(rays.tie + g, closer, same);
    }
  }
}

// PlueckerHitM::finalize: rcpUVW = |UVW| < 1e-18 ? 0 : rcp(UVW); u = min(U
// rcpUVW, 1), v = min(V rcpUVW, 1).
template <class L>
void finishLanes(BundleRays& rays) {
  using F = typename L::F;
  for (int g = 0; g < kBundleLanes; g += L::W) {
    const F UVW = L::load(rays.UVW + g);
    const F r = L::blend(L::lt(L::abs(UVW), L::set(1e-18f)), L::set(0.0f), L::rcp(UVW));
    L::store(rays.u + g, L::min(L::mul(L::load(rays.U + g), r), L::set(1.0f)));
    L::store(rays.v + g, L::min(L::mul(L::load(rays.V + g), r), L::set(1.0f)));
  }
}

}  // namespace
}  // namespace tofsim::rays::detail
