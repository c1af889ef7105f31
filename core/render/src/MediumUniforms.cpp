#include "MediumUniforms.h"

namespace tofsim::render {

void setMediumExtinction(const gl::Program& program, const capture::Medium& medium) {
  program.set("uMediumSigmaT", medium.sigmaT());
}

void setMediumScattering(const gl::Program& program, const capture::Medium& medium) {
  program.set("uMediumSigmaS", medium.sigma_s_per_m);
  program.set("uMediumPhase", static_cast<int>(medium.phase));
  program.set("uMediumG", medium.g);
}

}  // namespace tofsim::render
