#include "tofsim/ir/MaterialVertex.h"

#include <algorithm>

namespace tofsim::ir {

MaterialResponses materialResponses(const scene::Scene& scene) {
  MaterialResponses r;
  r.baseOfMaterial.reserve(scene.materials.size());
  for (const scene::Material& m : scene.materials) {
    if (!m.scatteringDelay) {
      r.baseOfMaterial.push_back(0);
      continue;
    }
    // Materials with equal delays share a base kernel (fewer classes).
    const auto found = std::find(r.kernels.begin(), r.kernels.end(), *m.scatteringDelay);
    const auto index = found - r.kernels.begin();
    if (found == r.kernels.end()) r.kernels.push_back(*m.scatteringDelay);
    r.baseOfMaterial.push_back(static_cast<int32_t>(index) + 1);
  }
  return r;
}

uint32_t lightResponse(const MaterialResponses& responses, const capture::Light& light) {
  const auto m = static_cast<std::size_t>(light.surface_material);
  if (light.surface_material < 0 || m >= responses.baseOfMaterial.size()) return 0;
  return static_cast<uint32_t>(responses.baseOfMaterial[m]);
}

physics::ScatterVertex materialVertex(const scene::Material& m, int model, int32_t response) {
  physics::ScatterVertex v = physics::scatterVertex(model, m.albedo, m.metallic, m.roughness);
  v.response = response;
  return v;
}

std::vector<physics::ScatterVertex> materialVertices(const scene::Scene& scene, int model) {
  const MaterialResponses responses = materialResponses(scene);
  std::vector<physics::ScatterVertex> vertices;
  vertices.reserve(scene.materials.size());
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    vertices.push_back(materialVertex(scene.materials[i], model, responses.baseOfMaterial[i]));
  }
  return vertices;
}

}  // namespace tofsim::ir
