// Bytes -> a capture sequence config and its animated glTF (SequenceInput.h)
// -> config::loadRunConfig, scene::AnimatedScene::load and the scene at each
// frame time: what `tofsim render` does with a `sequence:` before the first
// frame renders (fuzz_config never loads the scene; fuzz_gltf has no config).
#include "FuzzFile.h"
#include "SequenceInput.h"
#include "tofsim/util/Error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  tofsim::fuzz::linkShippedScenes();
  const auto config = tofsim::fuzz::writeSequenceInput(tofsim::fuzz::workDir(), data, size);
  try {
    if (!tofsim::fuzz::sequenceFramesRenderable(tofsim::config::loadRunConfig(config, {}))) {
      __builtin_trap();
    }
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
