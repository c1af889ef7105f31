// Bytes -> config YAML -> config::loadRunConfig. The config sits next to a
// link to the shipped scenes/ folder, so `scene: scenes/cornell_box.gltf`
// resolves as in configs/.
#include <filesystem>

#include "FuzzFile.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/util/Error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  tofsim::fuzz::linkShippedScenes();
  const auto path = tofsim::fuzz::writeInput("input.yaml", data, size);
  try {
    tofsim::config::loadRunConfig(path, {});
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
