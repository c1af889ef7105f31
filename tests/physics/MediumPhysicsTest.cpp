// A homogeneous medium's phase functions and transmittance (shaders/
// medium.glsl): each phase function integrates to 1 over the sphere, the
// Henyey-Greenstein mean cosine is g, Rayleigh's forward and back lobes are
// twice its side lobe, transmittance is exp(-sigma_t d) per channel; a
// medium vertex scatters by albedo times its phase function at the
// scattering angle between -wi and wo.

#include <gtest/gtest.h>

#include <cmath>

#include "tofsim/capture/Medium.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/physics/ScatterVertex.h"

namespace tofsim::physics {
namespace {

// Integral over the sphere of phase(mu) and mu phase(mu): 2 pi int_-1^1 d mu,
// midpoint rule.
struct Moments {
  double norm = 0.0;
  double meanCos = 0.0;
};

Moments moments(int model, float g) {
  constexpr int kSteps = 200000;
  Moments m;
  for (int i = 0; i < kSteps; ++i) {
    const double mu = -1.0 + (i + 0.5) * 2.0 / kSteps;
    const double p = phaseFunction(model, g, static_cast<float>(mu));
    m.norm += 2.0 * M_PI * p * 2.0 / kSteps;
    m.meanCos += 2.0 * M_PI * mu * p * 2.0 / kSteps;
  }
  return m;
}

TEST(MediumPhysicsTest, EachPhaseFunctionIntegratesToOneAndHenyeyGreensteinsMeanCosineIsG) {
  EXPECT_NEAR(moments(PHASE_ISOTROPIC, 0.0f).norm, 1.0, 1e-5);
  EXPECT_NEAR(moments(PHASE_RAYLEIGH, 0.0f).norm, 1.0, 1e-5);
  EXPECT_NEAR(moments(PHASE_RAYLEIGH, 0.0f).meanCos, 0.0, 1e-5);
  for (float g : {-0.5f, 0.0f, 0.3f, 0.6f, 0.9f}) {
    const Moments m = moments(PHASE_HENYEY_GREENSTEIN, g);
    EXPECT_NEAR(m.norm, 1.0, 2e-4) << g;
    EXPECT_NEAR(m.meanCos, g, 2e-4) << g;
  }
  EXPECT_FLOAT_EQ(phaseRayleigh(1.0f), 2.0f * phaseRayleigh(0.0f));
  EXPECT_FLOAT_EQ(phaseRayleigh(-1.0f), phaseRayleigh(1.0f));
}

TEST(MediumPhysicsTest, TransmittanceIsExponentialPerChannel) {
  const glm::vec3 t = mediumTransmittance(glm::vec3(0.1f, 0.5f, 0.0f), 3.0f);
  EXPECT_FLOAT_EQ(t.x, std::exp(-0.3f));
  EXPECT_FLOAT_EQ(t.y, std::exp(-1.5f));
  EXPECT_FLOAT_EQ(t.z, 1.0f);
}

TEST(MediumPhysicsTest, AMediumVertexScattersByAlbedoTimesPhaseAtTheScatteringAngle) {
  const glm::vec3 albedo(0.8f, 0.7f, 0.6f);
  const glm::vec3 wi = glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f));  // toward the light
  const glm::vec3 wo = glm::normalize(glm::vec3(-0.5f, 0.1f, 0.6f));  // toward the viewer
  const ScatterVertex hg = mediumVertex(albedo, PHASE_HENYEY_GREENSTEIN, 0.6f);
  EXPECT_FALSE(scatterIsConstant(hg));
  const glm::vec3 f = scatter(hg, glm::vec3(0.0f), wi, wo).f;
  EXPECT_FLOAT_EQ(f.y, albedo.y * phaseHenyeyGreenstein(0.6f, glm::dot(-wi, wo)));
  // Straight through (wo = -wi) is the forward peak.
  EXPECT_GT(scatter(hg, glm::vec3(0.0f), wi, -wi).f.x, f.x);
  const ScatterVertex iso = mediumVertex(albedo, PHASE_ISOTROPIC, 0.0f);
  EXPECT_TRUE(scatterIsConstant(iso));
  EXPECT_EQ(scatter(iso, glm::vec3(0.0f), wi, wo).f, albedo / (4.0f * PI));
}

TEST(MediumPhysicsTest, TheMediumKnowsWhetherItIsThereAndItsAlbedo) {
  capture::Medium none;
  EXPECT_FALSE(none.present());
  capture::Medium fog;
  fog.sigma_s_per_m = glm::vec3(0.04f);
  fog.sigma_a_per_m = glm::vec3(0.01f, 0.0f, 0.04f);
  EXPECT_TRUE(fog.present());
  EXPECT_FLOAT_EQ(fog.sigmaT().x, 0.05f);
  EXPECT_FLOAT_EQ(fog.albedo().x, 0.8f);
  EXPECT_FLOAT_EQ(fog.albedo().y, 1.0f);
  EXPECT_FLOAT_EQ(fog.albedo().z, 0.5f);
}

}  // namespace
}  // namespace tofsim::physics
