#include "NodeTransforms.h"

#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::scene::detail {

namespace {

void visit(const GltfDocument& doc, int node, const glm::dmat4& parent, std::vector<int>& path,
           std::vector<NodeInstance>& out) {
  if (node < 0 || node >= static_cast<int>(doc.nodes.size())) {
    throw InputError(FileLoc{doc.file}, "node[" + std::to_string(node) + "]", "does not exist");
  }
  for (int onPath : path) {
    if (onPath == node) {
      throw InputError(FileLoc{doc.file}, "node[" + std::to_string(node) + "]",
                       "node hierarchy has a cycle");
    }
  }
  const glm::dmat4 world = parent * doc.nodes[node].local;
  out.push_back({node, world});
  path.push_back(node);
  for (int child : doc.nodes[node].children) visit(doc, child, world, path, out);
  path.pop_back();
}

}  // namespace

std::vector<NodeInstance> flattenNodes(const GltfDocument& doc) {
  std::vector<NodeInstance> out;
  std::vector<int> path;
  for (int root : doc.rootNodes) visit(doc, root, glm::dmat4(1.0), path, out);
  return out;
}

}  // namespace tofsim::scene::detail
