// Bytes -> .gltf (JSON) or .glb (binary, by its "glTF" magic) -> loadGltf:
// tinygltf's parsing plus tofsim's own conversion (accessors, indices,
// transforms, degenerate triangles, NaN/inf positions).
#include <cmath>
#include <cstring>

#include "FuzzFile.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/Error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const auto path = tofsim::fuzz::writeInput(binary ? "input.glb" : "input.gltf", data, size);
  try {
    tofsim::scene::LoadReport report;
    const tofsim::scene::Scene scene = tofsim::scene::loadGltf(path, &report);
    // What the renderer relies on: indices in range, finite positions and
    // cameras.
    for (const tofsim::scene::SceneCamera& c : scene.cameras) {
      if (!std::isfinite(c.fov_y_deg) || !std::isfinite(c.position_world.x) ||
          !std::isfinite(c.forward_world.x) || !std::isfinite(c.up_world.x)) {
        __builtin_trap();
      }
    }
    for (const tofsim::scene::Mesh& mesh : scene.meshes) {
      for (const uint32_t i : mesh.indices) {
        if (i >= mesh.positions_world.size()) __builtin_trap();
      }
      for (const auto& p : mesh.positions_world) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) __builtin_trap();
      }
    }
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
