#pragma once
// The one place a scene material becomes a scattering vertex, and the scene's
// table of them (index = material index) that both backends read: the CPU's
// hit path (hitVertex) and GL's gathers, whose G-buffer holds the material's
// index (surface_samples.glsl). A per-material parameter of the transport
// (a scatter or a temporal response, issue 41) is read from the material here
// and nowhere else; what the material's textures give is a per-point step
// (physics::texturedVertex).

#include <cstdint>
#include <vector>

#include "tofsim/capture/Light.h"
#include "tofsim/physics/ResponseClassTable.h"
#include "tofsim/physics/ScatterVertex.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::ir {

/// The scene's temporal responses: its distinct scattering delays (base
/// kernels 1..kernels.size(), physics::ResponseClassTable) in order of first
/// use by Scene::materials, and each material's base id (0: instant).
struct MaterialResponses {
  std::vector<physics::ResponseKernel> kernels;
  std::vector<int32_t> baseOfMaterial;
};
MaterialResponses materialResponses(const scene::Scene& scene);

/// The base kernel of the surface `light` stands on (Light::surface_material;
/// 0: none, or an instant material): the response classes' start kernel.
uint32_t lightResponse(const MaterialResponses& responses, const capture::Light& light);

/// The vertex of material `m` under model `model` (physics::VERTEX_*:
/// vertexModelOf render.materials), before its textures, with base kernel
/// `response` (materialResponses).
physics::ScatterVertex materialVertex(const scene::Material& m, int model, int32_t response = 0);

/// materialVertex of each of the scene's materials, in Scene::materials order,
/// with their base kernels of materialResponses.
std::vector<physics::ScatterVertex> materialVertices(const scene::Scene& scene, int model);

}  // namespace tofsim::ir
