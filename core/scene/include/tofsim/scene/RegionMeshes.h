#pragma once
// A participating medium's region (`media:`, issue 42): the closed glTF mesh
// it fills, taken out of the scene's surfaces (Scene::regions). A region is
// an interface, not a surface: index matched (no reflection, no refraction),
// invisible; a tank's glass is a mesh of its own.

#include <optional>
#include <string>

#include "tofsim/scene/Scene.h"

namespace tofsim::scene {

/// Takes the meshes whose glTF mesh or node name is `name` out of
/// scene.meshes and returns their triangles as one region, wound outwards
/// (a consistently wound mesh whose signed volume is negative is turned);
/// nullopt when no mesh has that name (scene unchanged).
std::optional<RegionMesh> takeRegionMesh(Scene& scene, const std::string& name);

/// Why `region` does not bound a volume: "" when it is closed (every edge,
/// by vertex position, shared by exactly two triangles that cross it in
/// opposite directions: watertight and consistently wound), else what is
/// wrong (an open edge, an edge of three triangles, inconsistent winding,
/// no volume), with one offending edge's end points.
std::string regionMeshProblem(const RegionMesh& region);

/// The axis-aligned box of a region's vertices.
Bounds regionBounds(const RegionMesh& region);

}  // namespace tofsim::scene
