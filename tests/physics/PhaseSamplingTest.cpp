// Phase-function sampling (shaders/medium.glsl: samplePhaseCosine,
// samplePhaseDirection): the sampled directions follow the phase function's
// density about the forward direction. Pearson chi-square over cells of equal
// probability in the cosine (from a quadrature of phaseFunction) times
// azimuth sectors, 200 000 samples, p = 1e-4; the same samples reject the
// density of a mis-parametrised lobe (g off by 0.05, Rayleigh read as
// isotropic), so the test can fail.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/util/Random.h"

namespace tofsim::physics {
namespace {

constexpr int kCosCells = 32;
constexpr int kPhiCells = 8;
constexpr int kSamples = 200000;

// Upper edges in mu of kCosCells cells of equal probability under the
// density 2 pi phaseFunction(model, g, mu) on [-1, 1] (midpoint quadrature).
std::vector<double> equalProbabilityEdges(int model, float g) {
  constexpr int kSteps = 400000;
  std::vector<double> edges;
  double cdf = 0.0;
  for (int i = 0; i < kSteps && static_cast<int>(edges.size()) < kCosCells - 1; ++i) {
    const double mu = -1.0 + (i + 0.5) * 2.0 / kSteps;
    cdf += 2.0 * M_PI * phaseFunction(model, g, static_cast<float>(mu)) * 2.0 / kSteps;
    if (cdf >= static_cast<double>(edges.size() + 1) / kCosCells) edges.push_back(mu + 1.0 / kSteps);
  }
  edges.push_back(1.0 + 1e-9);
  return edges;
}

// Chi-square of `samples` (cosine to the axis, azimuth in [0, 2 pi)) against
// the density of (model, g) with uniform azimuth.
double chiSquare(const std::vector<glm::dvec2>& samples, int model, float g) {
  const std::vector<double> edges = equalProbabilityEdges(model, g);
  std::vector<double> counts(kCosCells * kPhiCells, 0.0);
  for (const glm::dvec2& s : samples) {
    const int c = static_cast<int>(std::lower_bound(edges.begin(), edges.end(), s.x) - edges.begin());
    const int p = std::min(kPhiCells - 1, static_cast<int>(s.y / (2.0 * M_PI) * kPhiCells));
    counts[static_cast<std::size_t>(std::min(c, kCosCells - 1) * kPhiCells + p)] += 1.0;
  }
  const double expected = static_cast<double>(samples.size()) / counts.size();
  double chi2 = 0.0;
  for (const double n : counts) chi2 += (n - expected) * (n - expected) / expected;
  return chi2;
}

// Chi-square's 1 - 1e-4 quantile (Wilson-Hilferty), df = cells - 1.
double criticalValue() {
  const double df = kCosCells * kPhiCells - 1;
  const double z = 3.719;
  const double a = 2.0 / (9.0 * df);
  return df * std::pow(1.0 - a + z * std::sqrt(a), 3.0);
}

// Directions about a tilted forward axis, as (cosine to it, azimuth about it
// in the frame basisAround builds).
std::vector<glm::dvec2> sampleDirections(int model, float g, uint64_t seed) {
  const glm::vec3 forward = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
  const glm::mat3 frame = basisAround(forward);
  Pcg32 rng = Pcg32::forUnit(seed, 0);
  std::vector<glm::dvec2> out;
  out.reserve(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    const float u1 = rng.nextFloat();
    const float u2 = rng.nextFloat();
    const glm::vec3 w = samplePhaseDirection(model, g, forward, u1, u2);
    EXPECT_NEAR(glm::length(w), 1.0f, 1e-5f);
    const double mu = std::clamp(static_cast<double>(glm::dot(w, forward)), -1.0, 1.0);
    double phi = std::atan2(static_cast<double>(glm::dot(w, frame[1])),
                            static_cast<double>(glm::dot(w, frame[0])));
    if (phi < 0.0) phi += 2.0 * M_PI;
    out.emplace_back(mu, phi);
  }
  return out;
}

struct Lobe {
  int model;
  float g;
};

TEST(PhaseSamplingTest, SampledDirectionsFollowThePhaseFunction) {
  const Lobe lobes[] = {{PHASE_ISOTROPIC, 0.0f},         {PHASE_RAYLEIGH, 0.0f},
                        {PHASE_HENYEY_GREENSTEIN, 0.0f}, {PHASE_HENYEY_GREENSTEIN, 0.6f},
                        {PHASE_HENYEY_GREENSTEIN, -0.3f}, {PHASE_HENYEY_GREENSTEIN, 0.9f},
                        {PHASE_HENYEY_GREENSTEIN, 0.0005f}};
  for (const Lobe& lobe : lobes) {
    const std::vector<glm::dvec2> samples = sampleDirections(lobe.model, lobe.g, 7);
    EXPECT_LT(chiSquare(samples, lobe.model, lobe.g), criticalValue())
        << "model " << lobe.model << " g " << lobe.g;
  }
}

TEST(PhaseSamplingTest, TheSameSamplesRejectAWrongDensity) {
  const double critical = criticalValue();
  for (const float g : {0.6f, -0.3f, 0.9f}) {
    const std::vector<glm::dvec2> samples = sampleDirections(PHASE_HENYEY_GREENSTEIN, g, 11);
    EXPECT_GT(chiSquare(samples, PHASE_HENYEY_GREENSTEIN, g + 0.05f), critical) << g;
  }
  const std::vector<glm::dvec2> rayleigh = sampleDirections(PHASE_RAYLEIGH, 0.0f, 13);
  EXPECT_GT(chiSquare(rayleigh, PHASE_ISOTROPIC, 0.0f), critical);
}

TEST(PhaseSamplingTest, CosinesCoverTheirRangeAndRayleighIsSymmetric) {
  // The inverse CDFs at the ends of [0, 1) and in the middle.
  EXPECT_NEAR(samplePhaseCosine(PHASE_HENYEY_GREENSTEIN, 0.6f, 0.0f), -1.0f, 1e-5f);
  EXPECT_NEAR(samplePhaseCosine(PHASE_HENYEY_GREENSTEIN, 0.6f, 0.999999f), 1.0f, 1e-4f);
  EXPECT_NEAR(samplePhaseCosine(PHASE_RAYLEIGH, 0.0f, 0.0f), -1.0f, 1e-5f);
  EXPECT_NEAR(samplePhaseCosine(PHASE_RAYLEIGH, 0.0f, 0.5f), 0.0f, 1e-6f);
  for (const float u : {0.1f, 0.3f, 0.45f}) {
    EXPECT_NEAR(samplePhaseCosine(PHASE_RAYLEIGH, 0.0f, u),
                -samplePhaseCosine(PHASE_RAYLEIGH, 0.0f, 1.0f - u), 1e-5f);
  }
}

}  // namespace
}  // namespace tofsim::physics
