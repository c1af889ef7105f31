#pragma once
// What a run's outputs are a function of, as three FNV-1a 64 digests: the
// effective config (after every override), the bytes of the scene file and of
// every file it reads (external glTF buffers and images), and the tofsim
// version. A batch run whose recorded key equals the key of its config now is
// up to date; any difference names what changed (configs/README.md, Batch
// files). The seed is in the effective config, and the renders are
// deterministic, so nothing else decides the bytes.
//
// The key split in two: `render`, a digest of everything the volume and the
// render's own files depend on (the effective config without `sensors:`,
// the scene and the version), and `sense`, of the sensors alone. Runs of one
// render key differ only in their sensors: a batch renders one of them and
// senses the others from its saved volume (SharedRender.h).

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"

namespace tofsim::pipeline {

struct RunContentKey {
  std::string config;   ///< hex64 of config::effectiveConfigYaml
  std::string scene;    ///< hex64 over the scene file and the files it references
  std::string version;  ///< pipeline::kVersion, verbatim
  std::string render;   ///< hex64 over the config without sensors, the scene and the version
  std::string sense;    ///< hex64 of the effective `sensors:` list
  bool operator==(const RunContentKey&) const = default;
};

/// The scene file followed by the external files it references (glTF
/// buffers[].uri and images[].uri that are not data: URIs, percent-decoded,
/// resolved against the scene's folder), in document order. Throws InputError
/// when the scene cannot be read or parsed.
std::vector<std::filesystem::path> sceneInputFiles(const std::filesystem::path& scene);

/// The scene part of the key: each input file's name and digest, in order.
std::string sceneInputsDigest(const std::filesystem::path& scene);

/// The key of a loaded run config (`sceneDigest`: sceneInputsDigest of its
/// scene, when the caller already has it; computed when empty). Throws InputError when a scene
/// input cannot be read.
RunContentKey runContentKey(const config::RunConfig& config, const std::string& sceneDigest = "");

}  // namespace tofsim::pipeline
