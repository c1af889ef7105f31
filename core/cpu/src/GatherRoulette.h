#pragma once
// render.indirect.gather_pairs (core/physics/medium_vpl_scattering.md,
// "The surface gather sampled"): the CPU surface gather keeps a (pixel
// sample, VPL) pair with probability q = min(1, e / threshold) and weighs
// its light 1 / q (the camera-ray pass's roulette, physics::
// mediumRayVplSurvival), before the pair's visibility, its scattered
// radiance and its footprint deposit, so those run for the kept pairs only.
// e = the VPL's importance (mediumRayVplImportance: its mean flux, a medium
// VPL's over 4 pi) over the squared distance (no cosines: only the
// roulette's variance depends on e); the sample's threshold is the sum of
// its e over all the render's VPLs over gather_pairs, so about that many
// pairs are kept a sample, the nearest and brightest always. Unbiased: each
// pair's expected light is its light. The draws hash (VPL index, the
// sample's index in the render, the render's seed): the bytes do not depend
// on the batches, segments or threads.

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "GatherKernel.h"
#include "VplArrays.h"

namespace tofsim::cpu {

/// Each VPL's roulette importance (physics::mediumRayVplImportance).
std::vector<float> gatherImportance(const VplArrays& v);

/// The threshold of a sample at x: sum over every VPL of importance / d^2,
/// over `pairs`; 0 (every pair kept) with at most `pairs` VPLs.
float gatherThreshold(const glm::vec3& x, const VplArrays& v, const float* importance,
                      int32_t pairs);

/// Every lit sample's threshold and index among samples [0, count) of a
/// segment whose first is the render's sample `firstSample` (threads: the
/// backend's).
void setGatherThresholds(PixelSurface* surfaces, const unsigned char* lit, std::size_t count,
                         std::size_t firstSample, const VplArrays& v, const float* importance,
                         int32_t pairs, int threads);

/// The draws' seed from render.seed (set apart from the other draws').
uint32_t gatherRouletteSeed(uint64_t seed);

/// vplTerms' roulette over lanes [0, n) of VPLs [first, first + n), after its
/// distances: a dropped lane's bin becomes kNoLight, a kept one's weight
/// (terms.kept) 1 / q; keepAll = 1 for every lane where the sample's
/// threshold is 0.
void roulettePairs(const PixelSurface& s, const float* importance, uint32_t seed,
                   std::size_t first, std::size_t n, VplTerms& terms);

/// The kept lanes' radiance times their weight 1 / q (after every radiance
/// pass of vplTerms).
void weighKeptPairs(std::size_t n, VplTerms& terms);

}  // namespace tofsim::cpu
