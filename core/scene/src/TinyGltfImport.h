#pragma once
// Parses a .gltf/.glb with tinygltf and copies what the loader needs into a
// GltfDocument (buffers are moved, not copied).

#include <filesystem>

#include "GltfDocument.h"

namespace tofsim::scene::detail {

/// Throws InputError naming the file, with tinygltf's error text.
GltfDocument importGltf(const std::filesystem::path& path);

}  // namespace tofsim::scene::detail
