#pragma once
// The camera-ray pass's roulette (CpuMediumVpls.cpp; core/physics/
// medium_vpl_scattering.md, "Sampled") decided a block of VPLs at a time
// before any pair's exact estimate. A pair (ray, VPL k) is kept when its
// draw u < q = min(e / threshold, 1), e = mediumRayVplEstimate = importance x
// (the angle its span subtends) / height: two arctangents a pair, for every
// pair of the render (the fog box at 32 x 32: 23 M of them, a third of the
// render's time), of which ~4096 a ray are kept. The angle is at most pi, so
// bound = importance x kAngleBound / height >= e for every pair, and a pair
// with u >= min(bound / threshold, 1) is dropped by the exact test too: the
// filter drops those (most of them) with no arctangent, eight lanes per
// instruction, and the exact test decides the rest. The same pairs are kept,
// with the same draws: the bytes of the pass without the filter.

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

#include "GatherKernel.h"  // kVplBlock

namespace tofsim::cpu {

/// Above any angle mediumInterval's width can take (at most two arctangents'
/// pi / 2 each, rounded: 3.1415927f), by 2 %: the bound's float product and
/// quotient stay above the estimate's whatever their rounding.
constexpr float kAngleBound = 3.2f;

/// What the pairs of one camera ray (a pixel sample) share.
struct PairFilterRay {
  glm::vec3 origin{0.0f}, direction{0.0f};
  float radius = 0.0f;      ///< the VPLs' mediumVplRadius, m
  float threshold = 0.0f;   ///< the roulette's (0: every pair kept)
  uint32_t pixel = 0;       ///< the pair's draws: hash3(k, pixel, drawSeed)
  uint32_t drawSeed = 0;    ///< render's seed + the sample's index x stride
};

/// For VPLs [first, first + n), n <= kVplBlock, of positions p* and
/// importances (mediumRayVplImportance): maybe[i] = 1 where the exact
/// roulette may keep the pair, 0 where it drops it; bits[i] the pair's draw.
void filterMediumPairs(const PairFilterRay& ray, const float* px, const float* py, const float* pz,
                       const float* importance, std::size_t first, std::size_t n,
                       int32_t* maybe, uint32_t* bits);

}  // namespace tofsim::cpu
