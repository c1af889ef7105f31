#pragma once
// Issue 41: each glTF material's temporal response (scene::Material::
// scatteringDelay), from the config's `materials:` entry of its name or else
// from the material's glTF `extras`, which take the same `scattering_delay`
// keys (configs/README.md, "materials"): times as strings with a unit
// ("2.5 ns") or numbers in seconds, a table's file relative to the glTF's
// folder. A config entry replaces the extras' scattering_delay whole (entry by
// entry, not key by key: a kernel is never half from each; `scattering_delay:
// none` drops the extras' delay).

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::config {

/// The extras of each material as the loader gives them.
using MaterialExtras = std::vector<std::map<std::string, std::string>>;

/// The scatteringDelay of each material of `scene` (read from
/// config.scene_file; `extras`: its LoadReport::materialExtras, a material
/// past its end has none), in Scene::materials order. Throws InputError for a `materials:` name the
/// scene does not have (located at the entry, listing the scene's material names) and for bad
/// extras (located by the glTF file and the material's index and name). The classes the delays make
/// are checked where the renderer's rule is known (pipeline/ConfiguredScene.h).
std::vector<std::optional<physics::ResponseKernel>> materialDelays(const RunConfig& config,
                                                                   const scene::Scene& scene,
                                                                   const MaterialExtras& extras);

/// Sets them: scene.materials[i].scatteringDelay = materialDelays(...)[i].
void applyMaterialDelays(const RunConfig& config, scene::Scene& scene,
                         const MaterialExtras& extras);

}  // namespace tofsim::config
