#include "tofsim/capture/Light.h"

#include <algorithm>
#include <cmath>

namespace tofsim::capture {

float Light::angularProfile(const glm::vec3& direction) const {
  if (type == Type::Point) return 1.0f;
  // Keep in sync with spotProfile() in shaders/light.glsl.
  const float cosAngle = glm::dot(direction, direction_world);
  const float cosOuter = std::cos(glm::radians(cone_half_angle_deg));
  const float cosInner = std::cos(glm::radians(std::max(0.0f, cone_half_angle_deg - cone_falloff_deg)));
  if (cosAngle >= cosInner) return 1.0f;
  if (cosAngle <= cosOuter) return 0.0f;
  const float s = (cosAngle - cosOuter) / (cosInner - cosOuter);
  return s * s * (3.0f - 2.0f * s);
}

}  // namespace tofsim::capture
