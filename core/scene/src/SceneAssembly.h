#pragma once
// The document's node instances baked into a world-space Scene, with what
// placed each mesh and camera kept so that a new pose can re-bake them.

#include <cstddef>
#include <vector>

#include "GltfDocument.h"
#include "NodeTransforms.h"
#include "PrimitiveBuilder.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::scene::detail {

/// What made Scene::meshes[i]: a primitive under a node instance.
struct MeshSlot {
  std::size_t instance = 0;  ///< into SceneAssembly::instances
  PrimitiveRef primitive;
};

/// What made Scene::cameras[i]: a camera node instance.
struct CameraSlot {
  std::size_t instance = 0;
  int camera = -1;  ///< into GltfDocument::cameras
};

struct SceneAssembly {
  Scene scene;
  std::vector<NodeInstance> instances;  ///< flattenNodes order, parents first
  std::vector<MeshSlot> meshSlots;      ///< one per scene.meshes
  std::vector<CameraSlot> cameraSlots;  ///< one per scene.cameras
};

/// The scene of the nodes' own transforms (loadGltf's). A primitive that
/// leaves no triangle is dropped unless its instance is in `keepEmpty`
/// (per instance; empty = none), which keeps a slot for geometry an
/// animation may scale up from zero.
SceneAssembly assembleScene(const GltfDocument& doc, LoadReport& report,
                            const std::vector<bool>& keepEmpty = {});

/// Scene::meshes[slot] re-baked with its instance at `world` (name, node and
/// material kept from `rest`).
Mesh rebakeMesh(const GltfDocument& doc, const MeshSlot& slot, const Mesh& rest,
                const glm::dmat4& world);

/// A perspective camera node at `world`; throws InputError naming the node
/// when the pose is degenerate or the field of view unusable.
SceneCamera placeCamera(const GltfDocument& doc, const CameraSlot& slot, int node,
                        const glm::dmat4& world);

}  // namespace tofsim::scene::detail
