#pragma once
// Flattens the node hierarchy of the default scene into world matrices.

#include <glm/glm.hpp>

#include <vector>

#include "GltfDocument.h"

namespace tofsim::scene::detail {

struct NodeInstance {
  int node = -1;
  glm::dmat4 world{1.0};  ///< node-local to world (parent x ... x local)
};

/// Every node reachable from the root nodes, parents before children. A node
/// reached twice (instancing through several parents) appears twice. Throws
/// InputError for a bad node index or a cycle.
std::vector<NodeInstance> flattenNodes(const GltfDocument& doc);

}  // namespace tofsim::scene::detail
