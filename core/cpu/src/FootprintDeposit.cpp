#include "FootprintDeposit.h"

#include <immintrin.h>

#include <algorithm>
#include <cmath>

namespace tofsim::cpu {

void widenToWideKernel(const glm::vec3& kernel, int32_t bins, int32_t& first, int32_t& last) {
  first = std::min(first, physics::footprintKnotBin(kernel, 0, bins));
  last = std::max(last, std::min(physics::footprintKnotBin(kernel, 3, bins) + 2, bins - 1));
}

namespace {

// Two groups of eight bins hold every narrow kernel.
static_assert(physics::FOOTPRINT_DIRECT_BINS == 16);

// Pair p's kernel, energy and narrow bins, as vplTerms left them.
struct Contribution {
  glm::vec3 kernel;
  glm::vec3 energy;
  int32_t first;
  int32_t count;  ///< 0: a wide kernel
};

inline Contribution contributionOf(const VplTerms* terms, BlockPair p) {
  const VplTerms& t = terms[p.sample];
  const uint32_t k = p.lane;
  return {glm::vec3(t.centre[k], t.wide[k], t.narrow[k]), glm::vec3(t.r[k], t.g[k], t.b[k]),
          t.first[k], t.count[k]};
}

void depositFootprintsScalar(const VplTerms* terms, const BlockPair* pairs, std::size_t count,
                             int32_t bins, float* histogram, double* diff,
                             physics::OffAxisSums& lost, int32_t& first, int32_t& last) {
  for (std::size_t i = 0; i < count; ++i) {
    const Contribution c = contributionOf(terms, pairs[i]);
    if (c.count == 0) {
      physics::depositWide(diff, bins, c.kernel, c.energy, lost);
      widenToWideKernel(c.kernel, bins, first, last);
    } else {
      physics::depositNarrow(histogram, bins, c.kernel, c.energy, lost);
    }
  }
}

#pragma GCC push_options
#pragma GCC target("avx2")

// A narrow kernel's per-kernel values (footprintNarrowEdgeCdf's and
// footprintNarrowCdf's), one per lane.
struct NarrowConstants {
  __m256 frac, last, narrow, wide, total, perRamps, perWide, halfNarrow;
};

// footprintNarrowEdgeCdf(kernel, j) for the eight j with j + 1 = jp1: the
// same float operations, selects for its branches.
inline __m256 narrowEdgeCdf8(__m256 jp1, const NarrowConstants& k) {
  const __m256 zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1.0f);
  const __m256 s = _mm256_sub_ps(jp1, k.frac);
  const __m256 rising = _mm256_mul_ps(_mm256_mul_ps(s, s), k.perRamps);
  const __m256 plateau = _mm256_mul_ps(_mm256_sub_ps(s, k.halfNarrow), k.perWide);
  const __m256 r = _mm256_sub_ps(k.total, s);
  const __m256 falling = _mm256_sub_ps(one, _mm256_mul_ps(_mm256_mul_ps(r, r), k.perRamps));
  // s < narrow ? rising : (s <= wide ? plateau : falling)
  __m256 cdf = _mm256_blendv_ps(falling, plateau, _mm256_cmp_ps(s, k.wide, _CMP_LE_OQ));
  cdf = _mm256_blendv_ps(cdf, rising, _mm256_cmp_ps(s, k.narrow, _CMP_LT_OQ));
  // s <= 0 ? 0 : (s >= total ? 1 : inside)
  cdf = _mm256_blendv_ps(cdf, one, _mm256_cmp_ps(s, k.total, _CMP_GE_OQ));
  cdf = _mm256_blendv_ps(cdf, zero, _mm256_cmp_ps(s, zero, _CMP_LE_OQ));
  // float(j + 1) > last ? 1 : cdf
  return _mm256_blendv_ps(cdf, one, _mm256_cmp_ps(jp1, k.last, _CMP_GT_OQ));
}

// Adds masses m (bins b .. b + 7 of a narrow kernel) times the energy to
// out = the histogram at bin b, bins b .. b + rem - 1 only: three vectors of
// (bin, channel) floats, each entry out += m * e as depositInBin.
inline void addBins8(float* out, __m256 m, int32_t rem, __m256 e0, __m256 e1, __m256 e2) {
  const __m256i bin0 = _mm256_setr_epi32(0, 0, 0, 1, 1, 1, 2, 2);
  const __m256i bin1 = _mm256_setr_epi32(2, 3, 3, 3, 4, 4, 4, 5);
  const __m256i bin2 = _mm256_setr_epi32(5, 5, 6, 6, 6, 7, 7, 7);
  const __m256 p0 = _mm256_mul_ps(_mm256_permutevar8x32_ps(m, bin0), e0);
  const __m256 p1 = _mm256_mul_ps(_mm256_permutevar8x32_ps(m, bin1), e1);
  const __m256 p2 = _mm256_mul_ps(_mm256_permutevar8x32_ps(m, bin2), e2);
  if (rem >= 8) {
    _mm256_storeu_ps(out, _mm256_add_ps(_mm256_loadu_ps(out), p0));
    _mm256_storeu_ps(out + 8, _mm256_add_ps(_mm256_loadu_ps(out + 8), p1));
    _mm256_storeu_ps(out + 16, _mm256_add_ps(_mm256_loadu_ps(out + 16), p2));
    return;
  }
  // The bins past the kernel are neither written nor read (a masked load
  // does not fault): they may be the next pixel's, another thread's.
  const __m256i r = _mm256_set1_epi32(rem);
  const __m256i m0 = _mm256_cmpgt_epi32(r, bin0);
  const __m256i m1 = _mm256_cmpgt_epi32(r, bin1);
  const __m256i m2 = _mm256_cmpgt_epi32(r, bin2);
  _mm256_maskstore_ps(out, m0, _mm256_add_ps(_mm256_maskload_ps(out, m0), p0));
  _mm256_maskstore_ps(out + 8, m1, _mm256_add_ps(_mm256_maskload_ps(out + 8, m1), p1));
  if (rem > 5) _mm256_maskstore_ps(out + 16, m2, _mm256_add_ps(_mm256_maskload_ps(out + 16, m2), p2));
}

// physics::depositNarrow's masses (each edge's CDF once, mass = upper -
// lower) and deposit, eight bins per instruction.
inline void depositNarrowAvx2(float* histogram, int32_t bins, const glm::vec3& kernel,
                              int32_t first, int32_t count, const glm::vec3& energy,
                              physics::OffAxisSums& lost) {
  const glm::vec2 e = physics::footprintLocalExtent(kernel);
  const float wide = kernel.y, narrow = kernel.z;
  NarrowConstants k;
  k.frac = _mm256_set1_ps(e.x - std::floor(e.x));
  k.last = _mm256_set1_ps(std::floor(e.y) - std::floor(e.x));
  k.narrow = _mm256_set1_ps(narrow);
  k.wide = _mm256_set1_ps(wide);
  k.total = _mm256_set1_ps(wide + narrow);
  k.perRamps = _mm256_set1_ps(1.0f / (2.0f * wide * narrow));
  k.perWide = _mm256_set1_ps(1.0f / wide);
  k.halfNarrow = _mm256_set1_ps(0.5f * narrow);
  // Each bin's lower edge is the previous bin's upper one (0 below the first).
  const __m256i previous = _mm256_setr_epi32(7, 0, 1, 2, 3, 4, 5, 6);
  const __m256 upper0 = narrowEdgeCdf8(_mm256_setr_ps(1, 2, 3, 4, 5, 6, 7, 8), k);
  const __m256 rotated0 = _mm256_permutevar8x32_ps(upper0, previous);
  const __m256 mass0 =
      _mm256_sub_ps(upper0, _mm256_blend_ps(rotated0, _mm256_setzero_ps(), 0x01));
  __m256 mass1 = _mm256_setzero_ps();
  if (count > 8) {
    const __m256 upper1 = narrowEdgeCdf8(_mm256_setr_ps(9, 10, 11, 12, 13, 14, 15, 16), k);
    const __m256 rotated1 = _mm256_permutevar8x32_ps(upper1, previous);
    mass1 = _mm256_sub_ps(upper1, _mm256_blend_ps(rotated1, rotated0, 0x01));
  }
  if (first < 0 || first + count > bins) {
    // Some bins off the axis: bin by bin, as depositNarrow.
    alignas(32) float mass[16];
    _mm256_store_ps(mass, mass0);
    _mm256_store_ps(mass + 8, mass1);
    for (int32_t j = 0; j < count; ++j) {
      physics::depositInBin(histogram, bins, first + j, mass[j], energy, lost);
    }
    return;
  }
  const float r = energy.r, g = energy.g, b = energy.b;
  const __m256 e0 = _mm256_setr_ps(r, g, b, r, g, b, r, g);
  const __m256 e1 = _mm256_setr_ps(b, r, g, b, r, g, b, r);
  const __m256 e2 = _mm256_setr_ps(g, b, r, g, b, r, g, b);
  float* out = histogram + static_cast<std::size_t>(first) * 3;
  addBins8(out, mass0, count, e0, e1, e2);
  if (count > 8) addBins8(out + 24, mass1, count - 8, e0, e1, e2);
}

void depositFootprintsAvx2(const VplTerms* terms, const BlockPair* pairs, std::size_t count,
                           int32_t bins, float* histogram, double* diff,
                           physics::OffAxisSums& lost, int32_t& first, int32_t& last) {
  for (std::size_t i = 0; i < count; ++i) {
    const Contribution c = contributionOf(terms, pairs[i]);
    if (c.count == 0) {
      physics::depositWide(diff, bins, c.kernel, c.energy, lost);
      widenToWideKernel(c.kernel, bins, first, last);
    } else {
      depositNarrowAvx2(histogram, bins, c.kernel, c.first, c.count, c.energy, lost);
    }
  }
}

void depositNarrowKernelAvx2(float* histogram, int32_t bins, const glm::vec3& kernel,
                             int32_t first, int32_t count, const glm::vec3& energy,
                             physics::OffAxisSums& lost) {
  depositNarrowAvx2(histogram, bins, kernel, first, count, energy, lost);
}

#pragma GCC pop_options

bool hasAvx2() {
  static const bool avx2 = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return avx2;
}

}  // namespace

void depositFootprints(const VplTerms* terms, const BlockPair* pairs, std::size_t count,
                       int32_t bins, float* histogram, double* diff, physics::OffAxisSums& lost,
                       int32_t& first, int32_t& last) {
  if (hasAvx2()) {
    depositFootprintsAvx2(terms, pairs, count, bins, histogram, diff, lost, first, last);
  } else {
    depositFootprintsScalar(terms, pairs, count, bins, histogram, diff, lost, first, last);
  }
}

void depositNarrowKernel(float* histogram, int32_t bins, const glm::vec3& kernel, int32_t first,
                         int32_t count, const glm::vec3& energy, physics::OffAxisSums& lost) {
  if (hasAvx2()) {
    depositNarrowKernelAvx2(histogram, bins, kernel, first, count, energy, lost);
  } else {
    physics::depositNarrow(histogram, bins, kernel, energy, lost);
  }
}

}  // namespace tofsim::cpu
