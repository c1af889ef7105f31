#pragma once
// Where a light's RSM rays can find a surface at all, so that the texels that
// look elsewhere need no ray: a Lambertian light on a planar mesh (the laser
// spot on a relay wall) lights every mesh but that plane, and in an NLOS
// scene those meshes fill a small part of its hemisphere. The rays it skips
// would have missed: the VPLs are the same.

#include <optional>
#include <vector>

#include "tofsim/capture/Light.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::cpu {

class LitBounds {
 public:
  explicit LitBounds(const scene::Scene& scene);
  /// The box around every mesh `light` can light, or nothing when that is
  /// every mesh (a point or spot light, or a Lambertian light on no mesh).
  std::optional<scene::Bounds> of(const capture::Light& light) const;

 private:
  struct MeshBox {
    scene::Bounds box;
    bool planar = false;
    glm::vec3 normal{0.0f};  ///< planar meshes: unit
    float offset = 0.0f;     ///< planar meshes: normal . x on the plane
  };
  std::vector<MeshBox> meshes_;
  float epsilon_m_ = 1e-6f;
};

/// Whether the ray from `origin` along `direction` (unit) meets `box`.
bool rayMeetsBox(const glm::vec3& origin, const glm::vec3& direction, const scene::Bounds& box);

}  // namespace tofsim::cpu
