#include "LightUniforms.h"

namespace tofsim::render {

void setLightUniforms(const gl::Program& program, const Light& light) {
  program.set("uLightPosition_world", light.position_world);
  program.set("uLightIntensity_W_per_sr", light.intensity_W_per_sr);
  const Light::ProfileTerms profile = light.profileTerms();
  program.set("uLightProfile", profile.kind);
  program.set("uLightDirection_world", profile.axis);
  program.set("uSpotCosOuter", profile.cosOuter);
  program.set("uSpotCosInner", profile.cosInner);
}

}  // namespace tofsim::render
