#pragma once
// `tofsim info SCENE.gltf`: what the loader made of a scene file, as text for
// people: meshes with triangle counts, bounds in metres, materials with
// albedo, cameras, and what the loader skipped or changed.

#include <filesystem>
#include <string>

namespace tofsim::pipeline {

/// Loads the scene (throws InputError like a render would) and describes it.
std::string describeScene(const std::filesystem::path& sceneFile);

}  // namespace tofsim::pipeline
