#include "GltfCameras.h"

#include <cmath>

namespace tofsim::scene::detail {

SceneCamera convertCamera(const CameraDesc& camera, const NodeInstance& instance) {
  const glm::dmat3 rot(instance.world);
  const glm::dvec3 forward = glm::normalize(rot * glm::dvec3(0.0, 0.0, -1.0));
  glm::dvec3 up = rot * glm::dvec3(0.0, 1.0, 0.0);
  up = glm::normalize(up - glm::dot(up, forward) * forward);  // remove shear
  SceneCamera out;
  out.name = camera.name;
  out.position_world = glm::vec3(instance.world[3]);
  out.forward_world = glm::vec3(forward);
  out.up_world = glm::vec3(up);
  out.fov_y_deg = static_cast<float>(camera.yfov_rad * 180.0 / M_PI);
  out.aspect = static_cast<float>(camera.aspectRatio);
  return out;
}

}  // namespace tofsim::scene::detail
