#pragma once
// extensionsRequired checked before tinygltf parses the file: tinygltf fails on
// e.g. Draco-compressed files with a misleading "accessor[0] invalid
// bufferView", so unsupported required extensions are reported first.

#include <filesystem>
#include <string>
#include <vector>

namespace tofsim::scene::detail {

/// The file's extensionsRequired (.gltf JSON or the .glb JSON chunk). Returns
/// an empty list when the JSON cannot be read; tinygltf then reports why.
std::vector<std::string> readRequiredExtensions(const std::filesystem::path& path);

/// Throws InputError "required extension X is not supported" for the first
/// required extension the loader cannot honour.
void checkRequiredExtensions(const std::filesystem::path& path);

}  // namespace tofsim::scene::detail
