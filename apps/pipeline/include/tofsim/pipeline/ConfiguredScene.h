#pragma once
// The scene a config renders: the glTF with each material's temporal
// response (issue 41) from the config's `materials:` or the glTF extras
// (config/MaterialDelays.h), checked against the IR renderer's response
// classes. Every path that loads a scene to render a config goes through
// here: the CLI's render and validate, batch workers (PreparedRenderer), a
// sequence's rest scene, NLOS scans, Python.

#include "tofsim/config/RunConfig.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::pipeline {

/// loadGltf(config.scene_file) and configureScene.
scene::Scene loadConfiguredScene(const config::RunConfig& config,
                                 scene::LoadReport* report = nullptr);

/// On a scene read from config.scene_file with the loader's `report`:
/// config::applyMaterialDelays (the extras from the report),
/// takeMediumRegions, then checkResponseClasses.
void configureScene(const config::RunConfig& config, scene::Scene& scene,
                    const scene::LoadReport& report);

/// The meshes of `media:`'s regions taken out of scene.meshes into
/// scene.regions (scene::takeRegionMesh), in order; an InputError located at
/// the entry's `region` for a name the scene lacks, a mesh that is not
/// closed (scene::regionMeshProblem) or regions whose boxes overlap.
void takeMediumRegions(const config::RunConfig& config, scene::Scene& scene);

/// The IR renderer's classes of `scene`'s delays (physics::ResponseClassTable
/// of its distinct kernels, ir::materialResponses, on paths of up to
/// render.indirect.bounces + 1 delayed vertices) within
/// physics::kMaxResponseClasses; else an InputError located at `materials:`
/// naming render.indirect.bounces and the delayed materials. The reference
/// samples each vertex's delay and has no classes.
void checkResponseClasses(const config::RunConfig& config, const scene::Scene& scene);

}  // namespace tofsim::pipeline
