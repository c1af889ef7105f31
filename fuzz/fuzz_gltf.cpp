// Bytes -> .gltf (JSON) or .glb (binary, by its "glTF" magic) -> loadGltf:
// tinygltf's parsing plus tofsim's own conversion (accessors, indices,
// transforms, degenerate triangles, NaN/inf positions); then AnimatedScene
// (animation channels, samplers, keyframes) at its first, middle and last
// keyframe times and beyond.
#include <cstring>

#include "FuzzFile.h"
#include "SceneInvariants.h"
#include "tofsim/scene/AnimatedScene.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/Error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const auto path = tofsim::fuzz::writeInput(binary ? "input.glb" : "input.gltf", data, size);
  try {
    tofsim::scene::LoadReport report;
    const tofsim::scene::Scene scene = tofsim::scene::loadGltf(path, &report);
    if (!tofsim::fuzz::renderable(scene)) __builtin_trap();
  } catch (const tofsim::InputError&) {
  }
  try {
    const auto animated = tofsim::scene::AnimatedScene::load(path);
    const double start = animated.start_s(), end = animated.end_s();
    for (const double t : {start - 1.0, start, 0.5 * (start + end), end, end + 1.0}) {
      if (!tofsim::fuzz::renderable(animated.sceneAt(t))) __builtin_trap();
    }
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
