#include "tofsim/capture/ThinLens.h"

#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::capture {

glm::vec2 aperturePoint(int32_t index, int32_t count) {
  TOFSIM_CHECK(count >= 1 && index >= 0 && index < count);
  // The golden angle pi (3 - sqrt 5): each new point falls in the widest gap
  // the earlier ones left, so any prefix of angles is near uniform.
  const double goldenAngle = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  const double r = std::sqrt((index + 0.5) / count);
  const double phi = goldenAngle * index;
  return {static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi))};
}

int32_t apertureSamplesOf(const Imager& imager) {
  const Camera* camera = cameraOf(imager);
  return camera != nullptr && camera->defocused() ? camera->aperture_samples : 1;
}

ThinLens::ThinLens(const Camera& camera)
    : centre_(camera.position_world),
      forward_(camera.forward()),
      right_(camera.right()),
      up_(camera.up()),
      radius_m_(0.5f * camera.aperture_m),
      focus_m_(camera.focus_distance_m) {
  TOFSIM_CHECK(focus_m_ > 0.0f);
}

ApertureRay ThinLens::through(const PrimaryRay& chief, glm::vec2 disk) const {
  // The chief ray meets the plane in focus (forward . (p - centre) = z_f)
  // after z_f / cos(angle to the axis).
  const glm::vec3 toFocus = chief.direction * (focus_m_ / glm::dot(chief.direction, forward_));
  const glm::vec3 inFocus = chief.origin + toFocus;
  const glm::vec3 offset = radius_m_ * (disk.x * right_ + disk.y * up_);  // a - c
  const glm::vec3 origin = centre_ + offset;
  const glm::vec3 ray = inFocus - origin;
  // |F - c| - |F - a| = (|F - c|^2 - |F - a|^2) / (|F - c| + |F - a|), the
  // numerator 2 (F - c).(a - c) - |a - c|^2: no cancellation of two ~z_f lengths.
  const float fromCentre = glm::length(toFocus), fromAperture = glm::length(ray);
  const float lensPath =
      (2.0f * glm::dot(toFocus, offset) - glm::dot(offset, offset)) / (fromCentre + fromAperture);
  return {{origin, ray / fromAperture}, lensPath};
}

double circleOfConfusion_px(const Camera& camera, double depth_m) {
  // The angle one pixel spans at the image centre: the pinhole's 2 tan(fov/2)
  // / height, a lens's 1 / fy.
  const double pixel =
      camera.lens ? 1.0 / camera.lens->fy
                  : 2.0 * std::tan(glm::radians(double(camera.fov_y_deg)) * 0.5) / camera.height;
  const double zf = camera.focus_distance_m;
  return camera.aperture_m * std::fabs(depth_m - zf) / (depth_m * zf) / pixel;
}

}  // namespace tofsim::capture
