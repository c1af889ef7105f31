// render.indirect.gather_pairs (core/cpu/src/GatherRoulette.h): the surface
// gather's roulette keeps about N pairs a sample and weighs each kept pair's
// light by 1 / q, so a pixel's light per bin averaged over the draws is the
// light of every pair. 3000 Lambertian VPLs of varied flux on a wall, a
// pixel on the floor before it, 256 pairs a sample: over 3000 draws (the
// sample's index) the mean histogram equals the full gather's within 1 % in
// total and 4 % in each of its bins of more than 2 % of the light, while
// fewer than a fifth of the pairs are kept. Fails without the 1 / q weight
// (weighKeptPairs) or with the draws fixed.

#include <gtest/gtest.h>

#include <map>
#include <random>

#include "GatherKernel.h"
#include "GatherRoulette.h"

namespace tofsim::cpu {
namespace {

TEST(GatherRouletteTest, TheMeanOverDrawsIsTheFullGatherWithAFewPairsKept) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  // Wall x = 0 facing +x; the floor y = 0 facing +y.
  std::vector<ir::Vpl> vpls(3000);
  for (ir::Vpl& v : vpls) {
    v.positionPath = glm::vec4(0.0f, 0.05f + 1.5f * u(rng), 2.0f * u(rng) - 1.0f, 1.0f + u(rng));
    v.normal = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    const float f = 0.1f + 2.0f * u(rng) * u(rng);
    v.flux = glm::vec4(f, 0.5f * f, 0.25f * f, 0.0f);
  }
  const VplArrays arrays(vpls);
  const std::vector<float> importance = gatherImportance(arrays);
  GatherConstants c;
  c.start_m = 0.0f, c.binWidth_m = 0.25f, c.indexOfRefraction = 1.0f, c.bins = 64;
  PixelSurface s;
  s.x = glm::vec3(0.3f, 0.0f, 0.1f);
  s.n = glm::vec3(0.0f, 1.0f, 0.0f);
  s.brdf = glm::vec3(0.2f);
  s.camera = glm::vec3(1.0f, 1.0f, 0.0f);
  s.cameraPath_m = glm::length(s.camera - s.x);
  const auto gather = [&](const GatherConstants& constants, std::map<int, double>& bins) {
    std::size_t kept = 0;
    for (std::size_t first = 0; first < vpls.size(); first += kVplBlock) {
      const std::size_t n = std::min(kVplBlock, vpls.size() - first);
      VplTerms terms;
      vplTerms(s, arrays, first, n, constants, terms);
      for (std::size_t i = 0; i < n; ++i) {
        if (terms.bin[i] == kNoLight) continue;
        bins[terms.bin[i]] += terms.r[i] + terms.g[i] + terms.b[i];
        ++kept;
      }
    }
    return kept;
  };
  std::map<int, double> full;
  const std::size_t lit = gather(c, full);
  GatherConstants sampled = c;
  sampled.rouletteImportance = importance.data();
  sampled.rouletteSeed = gatherRouletteSeed(1);
  s.rouletteThreshold = gatherThreshold(s.x, arrays, importance.data(), 256);
  ASSERT_GT(s.rouletteThreshold, 0.0f);
  std::map<int, double> mean;
  std::size_t kept = 0;
  const int draws = 3000;
  for (int d = 0; d < draws; ++d) {
    s.rouletteSample = static_cast<uint32_t>(d);
    kept += gather(sampled, mean);
  }
  double total = 0.0, meanTotal = 0.0;
  for (const auto& [bin, light] : full) total += light;
  for (const auto& [bin, light] : mean) meanTotal += light / draws;
  EXPECT_NEAR(meanTotal / total, 1.0, 0.01);
  for (const auto& [bin, light] : full) {
    if (light < 0.02 * total) continue;
    EXPECT_NEAR(mean[bin] / draws / light, 1.0, 0.04) << "bin " << bin;
  }
  const double keptPerDraw = static_cast<double>(kept) / draws;
  EXPECT_LT(keptPerDraw, 0.2 * static_cast<double>(lit));
  EXPECT_GT(keptPerDraw, 16.0);
}

}  // namespace
}  // namespace tofsim::cpu
