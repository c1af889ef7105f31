#pragma once
// Private to core/rays: a BVH of the scene's triangles of its own, for
// bundles of rays from one origin within a narrow cone (a lidar beam's
// receiver rays, or neighbouring beams' single rays). A node is tested once
// per bundle, against the pyramid that holds the bundle's rays (four
// planes through the origin) and against the farthest hit so far; at the
// leaves, the triangles the pyramid may touch are tested against every ray
// at once (BundleLanes.h's kernels, Embree's own arithmetic). The hits are
// Embree's single-ray hits: same triangle, same t, same barycentrics, bit
// for bit; where two triangles give a ray the same t, which one Embree
// reports depends on its traversal order, so the ray is flagged for Embree.

#include <cstdint>
#include <vector>

#include "BundleLanes.h"

namespace tofsim::rays::detail {

/// Which kernels match the Embree kernels the device runs: Embree picks
/// its widest instruction set the CPU has (or the one its config names).
enum class BundleIsa { None, Avx2, Avx512 };
/// The instruction set Embree 3.13 picks on this CPU, of those the bundle
/// kernels exist for; `embreeIsa` (a device config's isa=, "" for none)
/// caps it as it caps Embree.
BundleIsa bundleIsaFor(const char* embreeIsa);

class BeamBvh {
 public:
  /// triangles: the scene's, in RayScene's order (mesh by mesh).
  BeamBvh(std::vector<BundleTriangle> triangles, BundleIsa isa);
  /// The same triangles (count and order as built), moved: the boxes refitted.
  void refit(const std::vector<BundleTriangle>& triangles);
  /// Traces the active rays of `rays` (origin and directions set): each
  /// ray's closest hit (hit, t, u, v; tie where Embree must decide). False,
  /// tracing nothing, where the bundle is too wide for one pyramid (rays
  /// more than ~45 degrees from their mean).
  bool trace(BundleRays& rays) const;
  const BundleTriangle& triangle(int32_t index) const { return triangles_[index]; }

  static constexpr int kLeafTriangles = 4;

 private:
  struct Node {  // its box as centre and half extents (what the tests use)
    struct {
      float x, y, z;
    } centre, half;
    int32_t first = 0;  ///< a leaf's first triangle; an inner node's left child (right = first + 1)
    int32_t count = 0;  ///< a leaf's triangles, 0 for an inner node
  };
  struct Item;
  void build(std::vector<Item>& items, int32_t node, int32_t begin, int32_t end, int depth);
  void refitBoxes();

  std::vector<BundleTriangle> triangles_;  ///< in leaf order
  std::vector<int32_t> order_;             ///< triangles_[i] is the input's order_[i]
  std::vector<Node> nodes_;                ///< root first; children after their parent
  void (*intersect_)(BundleRays&, const BundleTriangle*, const int32_t*, int) = nullptr;
  void (*finish_)(BundleRays&) = nullptr;
};

}  // namespace tofsim::rays::detail
