#include "tofsim/ir/MaterialVertex.h"

namespace tofsim::ir {

physics::ScatterVertex materialVertex(const scene::Material& m, int model) {
  return physics::scatterVertex(model, m.albedo, m.metallic, m.roughness);
}

std::vector<physics::ScatterVertex> materialVertices(const scene::Scene& scene, int model) {
  std::vector<physics::ScatterVertex> vertices;
  vertices.reserve(scene.materials.size());
  for (const scene::Material& m : scene.materials) vertices.push_back(materialVertex(m, model));
  return vertices;
}

}  // namespace tofsim::ir
