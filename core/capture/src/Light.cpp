#include "tofsim/capture/Light.h"

#include <algorithm>
#include <cmath>

#include "tofsim/physics/TransientPhysics.h"

namespace tofsim::capture {

float Light::angularProfile(const glm::vec3& direction) const {
  if (type == Type::Point) return 1.0f;
  if (type == Type::Lambertian) return std::max(0.0f, glm::dot(direction, direction_world));
  // The same falloff as spotProfile() in shaders/light.glsl: one copy of the math.
  const float cosAngle = glm::dot(direction, direction_world);
  const float cosOuter = std::cos(glm::radians(cone_half_angle_deg));
  const float cosInner =
      std::cos(glm::radians(std::max(0.0f, cone_half_angle_deg - cone_falloff_deg)));
  return physics::spotFalloff(cosAngle, cosOuter, cosInner);
}

Light::ProfileTerms Light::profileTerms() const {
  ProfileTerms t;
  t.kind = type == Type::Spot         ? physics::LIGHT_SPOT
           : type == Type::Lambertian ? physics::LIGHT_LAMBERTIAN
                                      : physics::LIGHT_POINT;
  t.axis = glm::normalize(direction_world);
  t.cosOuter = std::cos(glm::radians(cone_half_angle_deg));
  t.cosInner = std::cos(glm::radians(std::max(0.0f, cone_half_angle_deg - cone_falloff_deg)));
  return t;
}

}  // namespace tofsim::capture
