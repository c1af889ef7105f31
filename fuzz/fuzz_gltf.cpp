// Bytes -> .gltf (JSON) or .glb (binary, by its "glTF" magic) -> loadGltf:
// tinygltf's parsing plus tofsim's own conversion (accessors, indices,
// transforms, degenerate triangles, NaN/inf positions).
#include <cstring>

#include "FuzzFile.h"
#include "SceneInvariants.h"
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
  return 0;
}
