#pragma once
// The scene's triangles flattened to world-space corners, ordered for the
// BVH, with an area CDF so the GL compute shaders and the CPU backend sample
// the same points uniformly by area (ISM points); the GL also casts its shadow
// rays (exact visibility) through this BVH. No GL: plain arrays.

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "tofsim/scene/Scene.h"

namespace tofsim::scene {

struct BvhNode {
  glm::vec4 min;  ///< xyz bounds; w = first triangle (leaf) or right child (inner), as float bits
  glm::vec4 max;  ///< xyz bounds; w = triangle count (leaf, > 0) or 0 (inner), as float bits
};

struct TriangleSoup {
  std::vector<glm::vec4> corners;  ///< 3 per triangle, w = 1
  std::vector<float> areaCdf;      ///< inclusive prefix sum of areas / total, one per triangle
  std::vector<BvhNode> bvh;        ///< node 0 is the root; left child of inner node i is i + 1
  double totalArea_m2 = 0.0;
  int bvhDepth = 0;  ///< levels from the root to the deepest leaf

  std::size_t triangleCount() const { return corners.size() / 3; }
};

/// Flattens the scene, builds a BVH (binned SAH) and orders the triangles by
/// leaf. Deterministic: depends only on the scene.
TriangleSoup buildTriangleSoup(const Scene& scene);

}  // namespace tofsim::scene
