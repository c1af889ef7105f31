#pragma once
// One glTF primitive placed by a world matrix into a world-space triangle Mesh.

#include <glm/glm.hpp>

#include "GltfDocument.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::scene::detail {

struct PrimitiveRef {
  int mesh = -1;
  int primitive = -1;
  int uvSet = 0;  ///< TEXCOORD_n to read as Mesh::uvs
};

/// Converts strips and fans to lists, bakes `world` into positions and
/// normals (inverse transpose; winding flipped when det < 0), makes flat
/// normals when NORMAL is absent and drops zero-area triangles. Returns false
/// (and counts it) for points and lines. Throws InputError for bad data.
bool buildPrimitive(const GltfDocument& doc, const PrimitiveRef& ref, const glm::dmat4& world,
                    Mesh& out, LoadReport& report);

}  // namespace tofsim::scene::detail
