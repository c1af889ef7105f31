// The camera-ray pass's pair filter (core/cpu/src/MediumPairFilter.h): it
// must never drop a pair the exact roulette keeps (the pass's bytes are
// those without it), and it must drop most pairs without their arctangents
// (its point). Random rays through a 2 m box of VPLs of random importance,
// the threshold the render's (ir::mediumRayThreshold's form) for ~1/8 of the
// pairs kept: every kept pair passes the filter with its draw, and the
// filter drops at least half of all pairs.

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "MediumPairFilter.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/physics/ShaderRandom.h"

namespace tofsim::cpu {
namespace {

TEST(MediumPairFilterTest, KeepsEveryPairTheRouletteKeepsAndDropsMostOthers) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const std::size_t count = 3 * kVplBlock + 17;  // a partial last block
  std::vector<float> px(count), py(count), pz(count), importance(count);
  for (std::size_t k = 0; k < count; ++k) {
    px[k] = u(rng), py[k] = u(rng), pz[k] = u(rng);
    // Medium and surface VPLs' importances over three decades.
    importance[k] = std::pow(10.0f, 1.5f * u(rng));
  }
  const float radius = physics::mediumVplRadius(0.0f);  // the fog box's: no clamp
  float threshold = 0.0f;
  for (float w : importance) threshold += w;
  threshold *= physics::PI / 0.87f / (count / 8.0f);
  std::size_t pairs = 0, kept = 0, passed = 0;
  for (uint32_t pixel = 0; pixel < 64; ++pixel) {
    PairFilterRay ray;
    ray.origin = glm::vec3(0.9f * u(rng), 0.9f * u(rng), 0.9f);
    ray.direction = glm::normalize(glm::vec3(0.5f * u(rng), 0.5f * u(rng), -1.0f));
    const float surface = (ray.origin.z + 1.0f) / -ray.direction.z;
    ray.radius = radius, ray.threshold = threshold, ray.pixel = pixel, ray.drawSeed = 77u;
    for (std::size_t first = 0; first < count; first += kVplBlock) {
      const std::size_t n = std::min(kVplBlock, count - first);
      int32_t maybe[kVplBlock];
      uint32_t bits[kVplBlock];
      filterMediumPairs(ray, px.data(), py.data(), pz.data(), importance.data(), first, n, maybe,
                        bits);
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t k = first + i;
        const uint32_t draw = physics::hash3(static_cast<uint32_t>(k), pixel, 77u);
        ASSERT_EQ(bits[i], draw) << "pair " << k;
        // CpuMediumVpls.cpp's exact roulette.
        const physics::MediumRay exact = physics::mediumEmitterRay(
            ray.origin, ray.direction, glm::vec3(px[k], py[k], pz[k]), radius, surface, 0.0f);
        const float q = physics::mediumRayVplSurvival(
            physics::mediumRayVplEstimate(exact, importance[k]), threshold);
        const bool keep = physics::unitFloat(draw) < q;
        ++pairs;
        kept += keep;
        passed += maybe[i] != 0;
        if (keep) {
          EXPECT_NE(maybe[i], 0) << "pixel " << pixel << ", VPL " << k << ": q " << q;
        }
      }
    }
  }
  EXPECT_GT(kept, pairs / 20);      // the threshold keeps a share, not all or none
  EXPECT_LT(passed, pairs / 2);     // most pairs never reach their arctangents
  EXPECT_GE(passed, kept);
}

}  // namespace
}  // namespace tofsim::cpu
