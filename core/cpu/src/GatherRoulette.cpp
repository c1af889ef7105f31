#include "GatherRoulette.h"

#include <algorithm>

#include "ParallelFor.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/physics/ShaderRandom.h"

namespace tofsim::cpu {

namespace {

// importance / d^2, the pair's estimate, lane by lane (the same float
// operations in the threshold's sum and in the roulette).
inline float pairEstimate(float importance, float dist2) { return importance / dist2; }

}  // namespace

std::vector<float> gatherImportance(const VplArrays& v) {
  std::vector<float> importance(v.count);
  for (std::size_t k = 0; k < v.count; ++k) {
    importance[k] = physics::mediumRayVplImportance(glm::vec3(v.fr[k], v.fg[k], v.fb[k]),
                                                    glm::vec3(v.nx[k], v.ny[k], v.nz[k]));
  }
  return importance;
}

float gatherThreshold(const glm::vec3& x, const VplArrays& v, const float* importance,
                      int32_t pairs) {
  if (pairs <= 0 || v.count <= static_cast<std::size_t>(pairs)) return 0.0f;
  // In VPL order, in double: the same sum whatever the build's ISA.
  double sum = 0.0;
  for (std::size_t k = 0; k < v.count; ++k) {
    const float tx = x.x - v.px[k], ty = x.y - v.py[k], tz = x.z - v.pz[k];
    const float dist2 = tx * tx + ty * ty + tz * tz;
    if (dist2 > 0.0f) sum += pairEstimate(importance[k], dist2);
  }
  return static_cast<float>(sum / pairs);
}

void setGatherThresholds(PixelSurface* surfaces, const unsigned char* lit, std::size_t count,
                         std::size_t firstSample, const VplArrays& v, const float* importance,
                         int32_t pairs, int threads) {
  constexpr std::size_t kSamplesPerTask = 16;
  parallelFor((count + kSamplesPerTask - 1) / kSamplesPerTask, threads, [&](std::size_t task) {
    const std::size_t end = std::min(count, (task + 1) * kSamplesPerTask);
    for (std::size_t i = task * kSamplesPerTask; i < end; ++i) {
      surfaces[i].rouletteSample = static_cast<uint32_t>(firstSample + i);
      surfaces[i].rouletteThreshold =
          lit[i] ? gatherThreshold(surfaces[i].x, v, importance, pairs) : 0.0f;
    }
  });
}

uint32_t gatherRouletteSeed(uint64_t seed) {
  return physics::pcgHash(static_cast<uint32_t>(seed ^ (seed >> 32)) ^ 0x67617468u);
}

// target_clones as vplTerms: the same IEEE operations in both builds.
__attribute__((target_clones("avx2", "default"))) void roulettePairs(
    const PixelSurface& s, const float* importance, uint32_t seed, std::size_t first,
    std::size_t n, VplTerms& __restrict terms) {
  const float* __restrict w = importance + first;
  const float threshold = s.rouletteThreshold;
  const uint32_t sample = s.rouletteSample;
  const auto k0 = static_cast<uint32_t>(first);
  for (std::size_t i = 0; i < n; ++i) {
    const float dist = terms.dist[i];
    const float e = pairEstimate(w[i], dist * dist);
    // physics::mediumRayVplSurvival's q; a threshold of 0 keeps every lane.
    const float q = threshold > 0.0f ? std::min(e / threshold, 1.0f) : 1.0f;
    const uint32_t draw = physics::hash3(k0 + static_cast<uint32_t>(i), sample, seed);
    const bool keep = physics::unitFloat(draw) < q;
    terms.bin[i] = keep ? terms.bin[i] : kNoLight;
    terms.kept[i] = keep ? 1.0f / q : 0.0f;
  }
}

__attribute__((target_clones("avx2", "default"))) void weighKeptPairs(
    std::size_t n, VplTerms& __restrict terms) {
  for (std::size_t i = 0; i < n; ++i) {
    terms.r[i] *= terms.kept[i];
    terms.g[i] *= terms.kept[i];
    terms.b[i] *= terms.kept[i];
  }
}

}  // namespace tofsim::cpu
