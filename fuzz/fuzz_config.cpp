// Bytes -> config YAML -> config::loadRunConfig. The config sits next to a
// link to the shipped scenes/ folder, so `scene: scenes/cornell_box.gltf`
// resolves as in configs/. A config with `materials:` is applied to its
// scene too (config::applyMaterialDelays: names checked against the scene's,
// the glTF extras read).
#include <filesystem>

#include "FuzzFile.h"
#include "tofsim/config/MaterialDelays.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/Error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  tofsim::fuzz::linkShippedScenes();
  const auto path = tofsim::fuzz::writeInput("input.yaml", data, size);
  try {
    const tofsim::config::RunConfig config = tofsim::config::loadRunConfig(path, {});
    if (!config.materials.empty()) {
      tofsim::scene::LoadReport report;
      tofsim::scene::Scene scene = tofsim::scene::loadGltf(config.scene_file, &report);
      tofsim::config::applyMaterialDelays(config, scene, report.materialExtras);
    }
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
