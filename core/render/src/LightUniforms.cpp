#include "LightUniforms.h"

#include <algorithm>
#include <cmath>

namespace tofsim::render {

void setLightUniforms(const gl::Program& program, const Light& light) {
  program.set("uLightPosition_world", light.position_world);
  program.set("uLightDirection_world", glm::normalize(light.direction_world));
  program.set("uLightIntensity_W_per_sr", light.intensity_W_per_sr);
  // light.glsl's uLightProfile codes.
  const int profile = light.type == Light::Type::Spot         ? 1
                      : light.type == Light::Type::Lambertian ? 2
                                                              : 0;
  program.set("uLightProfile", profile);
  const float outer = light.cone_half_angle_deg;
  const float inner = std::max(0.0f, outer - light.cone_falloff_deg);
  program.set("uSpotCosOuter", std::cos(glm::radians(outer)));
  program.set("uSpotCosInner", std::cos(glm::radians(inner)));
}

}  // namespace tofsim::render
