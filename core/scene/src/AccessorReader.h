#pragma once
// Typed, bounds-checked reads of glTF accessors: any component type, any
// byteStride, normalized integers (KHR_mesh_quantization) and sparse
// substitution. Out-of-range data is an InputError naming the file and the
// accessor, never an out-of-bounds read.

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "GltfDocument.h"

namespace tofsim::scene::detail {

/// count x components values as double (normalized per the glTF rules when
/// accessor.normalized). `what` names the use in errors ("POSITION").
std::vector<double> readAccessor(const GltfDocument& doc, int accessor, const std::string& what);

std::vector<glm::vec3> readVec3(const GltfDocument& doc, int accessor, const std::string& what);
std::vector<glm::vec2> readVec2(const GltfDocument& doc, int accessor, const std::string& what);
/// Unsigned integer indices (UNSIGNED_BYTE/SHORT/INT).
std::vector<uint32_t> readIndices(const GltfDocument& doc, int accessor);

}  // namespace tofsim::scene::detail
