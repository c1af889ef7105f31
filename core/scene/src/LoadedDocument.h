#pragma once
// The steps every glTF load starts with, shared by loadGltf and
// AnimatedScene::load.

#include <filesystem>

#include "GltfDocument.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::scene::detail {

/// Checks the file exists and needs no unsupported extension, then imports it.
GltfDocument loadDocument(const std::filesystem::path& path);

/// Fills the report's counts of what no renderer plays: skins, morph
/// targets, and the animations themselves for a static load.
void reportIgnoredAnimationParts(const GltfDocument& doc, LoadReport& report);

}  // namespace tofsim::scene::detail
