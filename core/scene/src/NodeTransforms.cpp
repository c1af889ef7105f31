#include "NodeTransforms.h"

#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::scene::detail {

glm::dmat4 localMatrix(const NodeTrs& trs) {
  if (trs.matrix) return *trs.matrix;
  glm::dmat4 m(1.0);
  if (trs.translation) m = glm::translate(m, *trs.translation);
  if (trs.rotation) m *= glm::mat4_cast(*trs.rotation);
  if (trs.scale) m = glm::scale(m, *trs.scale);
  return m;
}

namespace {

void visit(const GltfDocument& doc, int node, int parentInstance, std::vector<int>& path,
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
  const glm::dmat4 parent = parentInstance >= 0 ? out[parentInstance].world : glm::dmat4(1.0);
  const glm::dmat4 world = parent * doc.nodes[node].local;
  const int self = static_cast<int>(out.size());
  out.push_back({node, parentInstance, world});
  path.push_back(node);
  for (int child : doc.nodes[node].children) visit(doc, child, self, path, out);
  path.pop_back();
}

}  // namespace

std::vector<NodeInstance> flattenNodes(const GltfDocument& doc) {
  std::vector<NodeInstance> out;
  std::vector<int> path;
  for (int root : doc.rootNodes) visit(doc, root, -1, path, out);
  return out;
}

}  // namespace tofsim::scene::detail
