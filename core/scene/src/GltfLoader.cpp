#include "tofsim/scene/GltfLoader.h"

#include <utility>

#include "LoadedDocument.h"
#include "SceneAssembly.h"

namespace tofsim::scene {

Scene loadGltf(const std::filesystem::path& path, LoadReport* reportOut) {
  const detail::GltfDocument doc = detail::loadDocument(path);
  LoadReport report;
  detail::SceneAssembly assembly = detail::assembleScene(doc, report);
  detail::reportIgnoredAnimationParts(doc, report);
  if (reportOut) *reportOut = std::move(report);
  return std::move(assembly.scene);
}

}  // namespace tofsim::scene
