#pragma once
// A glTF scene with its node animations: the world-space Scene at any time.
//
// Every animation of the file plays at once, on the same clock (seconds of
// scene time; each channel holds its first keyframe before it and its last
// after it). A channel moves its node and every node below it: the mesh
// instances' world-space triangles and the cameras there (lights configured
// with attach_to_camera follow the camera). Morph-target weights and skins
// are not played (LoadReport and Animation count them).
//
// The Scene at time t is the rest scene (loadGltf's, the nodes' own
// transforms) with only the moving meshes and cameras re-baked, so what does
// not move keeps its bytes, and a scene without animations, or a time at
// which every animated property holds its node's own value, is exactly
// loadGltf's. Scene::meshes keeps its slots over time: an animated mesh that
// has no triangle at rest (scaled to zero) keeps an empty slot.

#include <cstddef>
#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "tofsim/scene/Animation.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::scene {

class AnimatedScene {
 public:
  /// Loads as loadGltf does and reads the animations. Throws InputError
  /// naming the file, the animation and its channel or sampler for bad
  /// animation data (GltfLoader.h's errors otherwise): among them a zero
  /// rotation quaternion, and a keyframe that puts a mesh or a camera it
  /// moves beyond kMaxSceneCoordinate_m (Scene.h), checked at every
  /// keyframe's time (and CUBICSPLINE segments' middles), so that a
  /// sequence fails before its first frame; a frame between keyframes that
  /// still leaves the bound fails where it is baked.
  static AnimatedScene load(const std::filesystem::path& path, LoadReport* report = nullptr);

  AnimatedScene(AnimatedScene&&) noexcept;
  AnimatedScene& operator=(AnimatedScene&&) noexcept;
  ~AnimatedScene();

  /// The scene of the nodes' own transforms: loadGltf's, but for the empty
  /// slots of animated meshes that have no triangle at rest.
  const Scene& restScene() const;
  const std::vector<Animation>& animations() const;
  bool animated() const;  ///< some channel moves a mesh or a camera
  /// First and last keyframe over all animations, s (0, 0 without any).
  double start_s() const;
  double end_s() const;

  /// Indices into Scene::meshes / Scene::cameras of what an animation moves
  /// (its node or a node above it is animated); the rest never changes.
  const std::vector<std::size_t>& movingMeshes() const;
  const std::vector<std::size_t>& movingCameras() const;

  /// Node-to-world matrix of each Scene::meshes slot at t_s (the matrix baked
  /// into its positions; inverse transpose for its normals).
  std::vector<glm::dmat4> meshTransformsAt(double t_s) const;

  /// The world-space scene at t_s.
  Scene sceneAt(double t_s) const;
  /// Re-bakes only the moving meshes and cameras of `scene` (restScene() or
  /// an earlier sceneAt()) to t_s; what does not move is not touched.
  void updateScene(Scene& scene, double t_s) const;

 private:
  struct State;
  explicit AnimatedScene(std::unique_ptr<State> state);
  void checkKeyframeExtents() const;
  std::unique_ptr<State> state_;
};

}  // namespace tofsim::scene
