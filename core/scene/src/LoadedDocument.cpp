#include "LoadedDocument.h"

#include <system_error>
#include <utility>

#include "RequiredExtensions.h"
#include "TinyGltfImport.h"
#include "tofsim/util/Error.h"

namespace tofsim::scene::detail {

GltfDocument loadDocument(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(FileLoc{path.string()}, "", "glTF file not found");
  }
  checkRequiredExtensions(path);
  return importGltf(path);
}

void reportIgnoredAnimationParts(const GltfDocument& doc, LoadReport& report) {
  report.animations = doc.animations.size();
  report.skins = doc.skins;
  report.morphTargetMeshes = doc.morphTargetMeshes;
}

}  // namespace tofsim::scene::detail
