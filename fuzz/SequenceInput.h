#pragma once
// How fuzz_sequence turns its bytes into a capture sequence of an animated
// glTF, shared with the regression test (tests/hardening/FuzzRegressionTest)
// so both load an input alike: the config YAML, a NUL byte, then the scene
// (a .glb when it starts with "glTF", else a .gltf), which the config names
// as `scene: input.gltf` (or .glb); without a NUL the bytes are the config
// alone, next to a `scenes` link to configs/scenes (cornell_box_moving.gltf
// is animated). What a sequence relies on before it renders: the config
// loads, the scene and its animations load, and the scene at each frame time
// is renderable (SceneInvariants.h: finite, within the scene bound).

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "SceneInvariants.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/scene/AnimatedScene.h"

namespace tofsim::fuzz {

/// Writes the config (and the scene, if any) into `dir`; returns the
/// config's path.
inline std::filesystem::path writeSequenceInput(const std::filesystem::path& dir,
                                                const uint8_t* data, std::size_t size) {
  const auto* nul = static_cast<const uint8_t*>(std::memchr(data, 0, size));
  const std::size_t configSize = nul ? static_cast<std::size_t>(nul - data) : size;
  const std::filesystem::path config = dir / "sequence.yaml";
  std::ofstream(config, std::ios::binary)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(configSize));
  if (nul) {
    const uint8_t* scene = nul + 1;
    const std::size_t sceneSize = size - configSize - 1;
    const bool binary = sceneSize >= 4 && std::memcmp(scene, "glTF", 4) == 0;
    std::ofstream(dir / (binary ? "input.glb" : "input.gltf"), std::ios::binary)
        .write(reinterpret_cast<const char*>(scene), static_cast<std::streamsize>(sceneSize));
  }
  return config;
}

/// The config's sequence over its scene: false when a frame's scene is not
/// renderable (a bug: bad input must end in an InputError before it).
inline bool sequenceFramesRenderable(const config::RunConfig& config) {
  if (!config.sequence) return true;
  const scene::AnimatedScene animated = scene::AnimatedScene::load(config.scene_file);
  scene::Scene scene = animated.restScene();
  if (!renderable(scene)) return false;
  std::size_t frames = 0;
  for (const double t : config.sequence->times_s) {
    if (++frames > 64) break;  // a fuzz input's time is better spent elsewhere
    animated.updateScene(scene, t);
    if (!renderable(scene)) return false;
  }
  return true;
}

}  // namespace tofsim::fuzz
