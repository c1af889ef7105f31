// The medium VPL record (ir/MediumVpl.h): no side, the medium's phase
// function times its albedo toward every direction, its flux never the
// scatter's.
#include <gtest/gtest.h>

#include "tofsim/ir/MediumVpl.h"

namespace tofsim::ir {
namespace {

TEST(MediumVplTest, ScattersByTheMediumsPhaseFunctionAndHasNoSide) {
  capture::Medium fog;
  fog.sigma_a_per_m = glm::vec3(0.1f, 0.2f, 0.3f);
  fog.sigma_s_per_m = glm::vec3(0.9f, 0.8f, 0.7f);
  fog.phase = physics::PHASE_HENYEY_GREENSTEIN;
  fog.g = 0.6f;
  const glm::vec3 incoming(0.0f, 0.0f, 1.0f);  // the light came from +z
  const Vpl v = mediumVpl(glm::vec3(1.0f, 2.0f, 3.0f), 4.5f, glm::vec3(2.0f), incoming, fog, 3.0f);
  EXPECT_TRUE(isMediumVpl(v));
  EXPECT_EQ(v.positionPath, glm::vec4(1.0f, 2.0f, 3.0f, 4.5f));
  EXPECT_EQ(v.flux.w, 3.0f);
  EXPECT_FALSE(physics::vplFluxHoldsScatter(v.vertex));
  for (const glm::vec3 toX : {glm::vec3(0, 0, -1), glm::vec3(0, 0, 1), glm::vec3(1, 0, 0)}) {
    EXPECT_EQ(physics::vplEmitterCosine(glm::vec3(v.normal), toX), 1.0f);
    const glm::vec3 f = physics::vplScatter(v.vertex, glm::vec3(v.normal), incoming, toX, 0.0f);
    // Forward is along -incoming: cosTheta = dot(-incoming, toX).
    const float p = physics::phaseHenyeyGreenstein(0.6f, glm::dot(-incoming, toX));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], fog.albedo()[c] * p, 1e-6f * p) << c;
  }
  // A surface VPL keeps its side.
  EXPECT_FLOAT_EQ(physics::vplEmitterCosine(glm::vec3(0, 0, 1), glm::normalize(glm::vec3(1, 0, 1))),
                  glm::sqrt(0.5f));
}

}  // namespace
}  // namespace tofsim::ir
