#pragma once
// `tofsim info SCENE.gltf`: what the loader made of a scene file, as text for
// people: meshes with triangle counts, bounds in metres, materials with
// albedo, cameras (at rest: the nodes' own transforms), the animations (each
// one's span and channels, what it ignores) and what the loader skipped or
// changed.

#include <filesystem>
#include <string>

namespace tofsim::pipeline {

/// Loads the scene with its animations (throws InputError like a render
/// would, and for bad animation data) and describes it.
std::string describeScene(const std::filesystem::path& sceneFile);

}  // namespace tofsim::pipeline
