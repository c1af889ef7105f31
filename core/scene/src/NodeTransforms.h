#pragma once
// Flattens the node hierarchy of the default scene into world matrices.

#include <glm/glm.hpp>
#include <vector>

#include "GltfDocument.h"

namespace tofsim::scene::detail {

/// T x R x S of the properties present, or the matrix (the glTF rule).
glm::dmat4 localMatrix(const NodeTrs& trs);

struct NodeInstance {
  int node = -1;
  int parent = -1;        ///< index of the parent's instance in the flattened list, -1 for a root
  glm::dmat4 world{1.0};  ///< node-local to world (parent x ... x local)
};

/// Every node reachable from the root nodes, parents before children. A node
/// reached twice (instancing through several parents) appears twice. Throws
/// InputError for a bad node index or a cycle.
std::vector<NodeInstance> flattenNodes(const GltfDocument& doc);

}  // namespace tofsim::scene::detail
