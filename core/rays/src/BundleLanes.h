#pragma once
// Private to core/rays: a bundle of up to 16 rays from one origin (a lidar
// beam's receiver rays) as the leaf kernels see them, structure of arrays,
// and the kernels themselves. The kernels are compiled per instruction set
// (BundleKernelAvx512.cpp, BundleKernelAvx2.cpp, with their own -m flags),
// so this header holds plain data only: nothing here may emit code that a
// machine without those instructions could end up running.

#include <cstdint>

namespace tofsim::rays::detail {

constexpr int kBundleLanes = 16;

/// One triangle of the scene as the kernels read it: Embree's vertices (the
/// same floats RayScene copies into its geometry buffers) and its ids.
struct BundleTriangle {
  float v0[3], v1[3], v2[3];
  uint32_t mesh = 0, triangle = 0;
  /// Its unit normal as RayScene::completeHit works it out (not read by
  /// the kernels): worked out once, not once per hit.
  float normal[3] = {0.0f, 0.0f, 0.0f};
};

/// The rays of a bundle and, per ray, the closest hit found so far in
/// Embree's terms: t, and the Pluecker sums U, V, U + V + W of its triangle
/// (the barycentrics follow from them at the end, as Embree finalizes them).
struct alignas(64) BundleRays {
  float dx[kBundleLanes], dy[kBundleLanes], dz[kBundleLanes];
  float t[kBundleLanes];  ///< the closest hit's distance; +inf: none yet
  float U[kBundleLanes], V[kBundleLanes], UVW[kBundleLanes];
  int32_t hit[kBundleLanes];  ///< the closest hit's triangle (its index in `triangles`), -1: none
  int32_t tie[kBundleLanes];  ///< nonzero: another triangle gave the same t (Embree decides)
  /// The nearest t at which a triangle was accepted within rounding of its
  /// edge (+inf: none): where that is not beyond the closest hit, Embree decides.
  float edgeT[kBundleLanes];
  int32_t active[kBundleLanes];            ///< -1: a ray, 0: an empty lane
  float u[kBundleLanes], v[kBundleLanes];  ///< Embree's barycentrics, after finish
  float ox = 0.0f, oy = 0.0f, oz = 0.0f;
};

/// Intersects every active ray of `rays` with triangles[indices[0 .. count)] with
/// Embree 3.13's robust (Pluecker) triangle test, operation for operation
/// as its single-ray kernel of the same instruction set computes it, and
/// keeps each ray's closest hit (ties flagged).
void intersectAvx512(BundleRays& rays, const BundleTriangle* triangles, const int32_t* indices,
                     int count);
void intersectAvx2(BundleRays& rays, const BundleTriangle* triangles, const int32_t* indices,
                   int count);
/// Each hit ray's barycentrics (u, v) from its U, V, UVW, as Embree's
/// PlueckerHitM::finalize gives them.
void finishAvx512(BundleRays& rays);
void finishAvx2(BundleRays& rays);

}  // namespace tofsim::rays::detail
