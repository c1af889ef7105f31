// Bytes -> config YAML -> config::loadRunConfig. The config sits next to a
// link to the shipped scenes/ folder, so `scene: scenes/cornell_box.gltf`
// resolves as in configs/. A config with `materials:` is applied to its
// scene too (config::applyMaterialDelays: names checked against the scene's,
// the glTF extras read). A config with `medium:` reloads from its effective
// config to the same medium (issue 42: the content key and the batch resume
// rest on it). A config with `media:` has its regions taken out of its scene
// and checked (scene::takeRegionMesh, regionMeshProblem, as
// pipeline::takeMediumRegions does) and reloads to the same media.
#include <filesystem>

#include "FuzzFile.h"
#include "tofsim/config/MaterialDelays.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/scene/RegionMeshes.h"
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
    if (config.medium) {
      const tofsim::config::RunConfig again =
          tofsim::config::loadRunConfigText(tofsim::config::effectiveConfigYaml(config), path);
      const tofsim::capture::Medium& a = config.render.medium;
      const tofsim::capture::Medium& b = again.render.medium;
      if (a.sigma_a_per_m != b.sigma_a_per_m || a.sigma_s_per_m != b.sigma_s_per_m ||
          a.phase != b.phase || a.g != b.g ||
          config.render.time.index_of_refraction != again.render.time.index_of_refraction) {
        __builtin_trap();
      }
    }
    if (!config.render.media.empty()) {
      tofsim::scene::Scene scene = tofsim::scene::loadGltf(config.scene_file);
      for (const tofsim::capture::RegionMedium& m : config.render.media) {
        if (const auto region = tofsim::scene::takeRegionMesh(scene, m.region)) {
          (void)tofsim::scene::regionMeshProblem(*region);
        }
      }
      const tofsim::config::RunConfig again =
          tofsim::config::loadRunConfigText(tofsim::config::effectiveConfigYaml(config), path);
      if (again.render.media.size() != config.render.media.size()) __builtin_trap();
      for (std::size_t i = 0; i < config.render.media.size(); ++i) {
        const tofsim::capture::RegionMedium& a = config.render.media[i];
        const tofsim::capture::RegionMedium& b = again.render.media[i];
        if (a.region != b.region || a.medium.sigma_a_per_m != b.medium.sigma_a_per_m ||
            a.medium.sigma_s_per_m != b.medium.sigma_s_per_m || a.medium.phase != b.medium.phase ||
            a.medium.g != b.medium.g || a.index_of_refraction != b.index_of_refraction) {
          __builtin_trap();
        }
      }
    }
  } catch (const tofsim::InputError&) {
  }
  return 0;
}
