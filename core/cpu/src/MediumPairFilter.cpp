#include "MediumPairFilter.h"

#include <algorithm>
#include <cmath>

#include "tofsim/physics/ShaderRandom.h"

namespace tofsim::cpu {

// target_clones as vplTerms (GatherKernel.cpp): an AVX2 and a baseline build
// of the same IEEE operations (-ffp-contract=off), picked at load time.
__attribute__((target_clones("avx2", "default"))) void filterMediumPairs(
    const PairFilterRay& ray, const float* px, const float* py, const float* pz,
    const float* importance, std::size_t first, std::size_t n, int32_t* __restrict maybe,
    uint32_t* __restrict bits) {
  const float* __restrict x = px + first;
  const float* __restrict y = py + first;
  const float* __restrict z = pz + first;
  const float* __restrict w = importance + first;
  const float ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
  const float dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
  const float radius2 = ray.radius * ray.radius, threshold = ray.threshold;
  const uint32_t pixel = ray.pixel, seed = ray.drawSeed;
  const auto k0 = static_cast<uint32_t>(first);
  for (std::size_t i = 0; i < n; ++i) {
    // mediumEmitterRay's height, by its steps: the closest approach's
    // distance from the VPL, widened by the radius.
    const float ax = ox - x[i], ay = oy - y[i], az = oz - z[i];
    const float along = dx * ax + dy * ay + dz * az;
    const float qx = ax - along * dx, qy = ay - along * dy, qz = az - along * dz;
    const float miss = std::sqrt(qx * qx + qy * qy + qz * qz);
    const float height = std::sqrt(miss * miss + radius2);
    const uint32_t draw = physics::hash3(k0 + static_cast<uint32_t>(i), pixel, seed);
    const float bound = w[i] * kAngleBound / height;
    const float q = threshold > 0.0f ? std::min(bound / threshold, 1.0f) : 1.0f;
    bits[i] = draw;
    maybe[i] = physics::unitFloat(draw) < q;
  }
}

}  // namespace tofsim::cpu
