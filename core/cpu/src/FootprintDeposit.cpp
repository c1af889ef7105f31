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
  NarrowShape shape;
};

inline Contribution contributionOf(const VplTerms* terms, BlockPair p) {
  const VplTerms& t = terms[p.sample];
  const uint32_t k = p.lane;
  return {glm::vec3(t.centre[k], t.wide[k], t.narrow[k]), glm::vec3(t.r[k], t.g[k], t.b[k]),
          t.first[k], t.count[k], {t.frac[k], t.last[k], t.perRamps[k], t.perWide[k]}};
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
  if (rem > 5)
    _mm256_maskstore_ps(out + 16, m2, _mm256_add_ps(_mm256_maskload_ps(out + 16, m2), p2));
}

// physics::depositNarrow's masses (each edge's CDF once, mass = upper -
// lower) and deposit, eight bins per instruction.
inline void depositNarrowAvx2(float* histogram, int32_t bins, const glm::vec3& kernel,
                              const NarrowShape& shape, int32_t first, int32_t count,
                              const glm::vec3& energy, physics::OffAxisSums& lost) {
  const float wide = kernel.y, narrow = kernel.z;
  NarrowConstants k;
  k.frac = _mm256_set1_ps(shape.frac);
  k.last = _mm256_set1_ps(shape.last);
  k.narrow = _mm256_set1_ps(narrow);
  k.wide = _mm256_set1_ps(wide);
  k.total = _mm256_set1_ps(wide + narrow);
  k.perRamps = _mm256_set1_ps(shape.perRamps);
  k.perWide = _mm256_set1_ps(shape.perWide);
  k.halfNarrow = _mm256_set1_ps(0.5f * narrow);
  // Each bin's lower edge is the previous bin's upper one (0 below the first).
  const __m256i previous = _mm256_setr_epi32(7, 0, 1, 2, 3, 4, 5, 6);
  const __m256 upper0 = narrowEdgeCdf8(_mm256_setr_ps(1, 2, 3, 4, 5, 6, 7, 8), k);
  const __m256 rotated0 = _mm256_permutevar8x32_ps(upper0, previous);
  const __m256 mass0 = _mm256_sub_ps(upper0, _mm256_blend_ps(rotated0, _mm256_setzero_ps(), 0x01));
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

// footprintKinkWeight(p, k, step) for four kinks at once (k + 1 - p = t):
// the same double operations, selects for its branches.
inline __m256d kinkWeight4(__m256d t, bool step) {
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0), two = _mm256_set1_pd(2.0),
                three = _mm256_set1_pd(3.0), half = _mm256_set1_pd(0.5);
  const __m256d upToOne = _mm256_cmp_pd(t, one, _CMP_LE_OQ);
  const __m256d upToTwo = _mm256_cmp_pd(t, two, _CMP_LE_OQ);
  const __m256d outside =
      _mm256_or_pd(_mm256_cmp_pd(t, zero, _CMP_LE_OQ), _mm256_cmp_pd(t, three, _CMP_GT_OQ));
  __m256d w;
  if (step) {
    // f = 1 - t + floor(t); t <= 1: t; t <= 2: 2 f - 1; else -f.
    const __m256d f = _mm256_add_pd(_mm256_sub_pd(one, t), _mm256_floor_pd(t));
    const __m256d middle = _mm256_sub_pd(_mm256_mul_pd(two, f), one);
    const __m256d last = _mm256_xor_pd(f, _mm256_set1_pd(-0.0));  // -f
    w = _mm256_blendv_pd(_mm256_blendv_pd(last, middle, upToTwo), t, upToOne);
  } else {
    // t <= 1: t^2 / 2; t <= 2: (-2 t^2 + 6 t - 3) / 2; else (3 - t)^2 / 2.
    const __m256d first = _mm256_mul_pd(_mm256_mul_pd(half, t), t);
    const __m256d middle = _mm256_mul_pd(
        half, _mm256_sub_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(-2.0), t), t),
                                          _mm256_mul_pd(_mm256_set1_pd(6.0), t)),
                            three));
    const __m256d r = _mm256_sub_pd(three, t);
    const __m256d last = _mm256_mul_pd(_mm256_mul_pd(half, r), r);
    w = _mm256_blendv_pd(_mm256_blendv_pd(last, middle, upToTwo), first, upToOne);
  }
  return _mm256_blendv_pd(w, zero, outside);
}

// depositWideAvx2's slots when the kinks' bins are apart (no slot within
// reach of two kinks) and on the axis: every slot written, slot (j, o)'s sum
// over the kinks that of kink j's weight and zeros, taken lane by lane with
// the same operations as the general case's.
inline void addApartKinks(double* diff, const int32_t kb[4], const __m256d weight[3], bool step,
                          double scale, const glm::vec3& energy) {
  const __m256d all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  const __m256d kink0 = _mm256_blend_pd(_mm256_setzero_pd(), all, 0x1);
  const __m256d kink1 = _mm256_blend_pd(_mm256_setzero_pd(), all, 0x2);
  const __m256d kink2 = _mm256_blend_pd(_mm256_setzero_pd(), all, 0x4);
  const __m256d kink3 = _mm256_blend_pd(_mm256_setzero_pd(), all, 0x8);
  const __m256d scales = _mm256_set1_pd(scale);
  alignas(32) double value[3][4];
  for (int o = 0; o < 3; ++o) {
    const __m256d w0 = _mm256_and_pd(weight[o], kink0), w3 = _mm256_and_pd(weight[o], kink3);
    __m256d sum;
    if (step) {
      sum = _mm256_sub_pd(w0, w3);
    } else {
      const __m256d w1 = _mm256_and_pd(weight[o], kink1), w2 = _mm256_and_pd(weight[o], kink2);
      sum = _mm256_add_pd(_mm256_sub_pd(_mm256_sub_pd(w0, w1), w2), w3);
    }
    _mm256_store_pd(value[o], _mm256_mul_pd(scales, sum));
  }
  const __m128d rg = _mm_setr_pd(static_cast<double>(energy.r), static_cast<double>(energy.g));
  const __m128d bb = _mm_set_sd(static_cast<double>(energy.b));
  for (int j = 0; j < 4; ++j) {
    double* entry = diff + static_cast<std::size_t>(kb[j]) * 3;
    for (int o = 0; o < 3; ++o, entry += 3) {
      const __m128d v = _mm_set1_pd(value[o][j]);
      _mm_storeu_pd(entry, _mm_add_pd(_mm_loadu_pd(entry), _mm_mul_pd(v, rg)));
      _mm_store_sd(entry + 2, _mm_add_sd(_mm_load_sd(entry + 2), _mm_mul_sd(v, bb)));
    }
  }
}

// depositWideAvx2's slots in general: slot (j, o) writes bin kb[j] + o unless
// past the axis or already written by kink j - 1; its value sums the weights
// w[reach][i] of the kinks i within reach.
inline void addNearKinks(double* diff, int32_t bins, const int32_t kb[4], const double w[3][4],
                         bool step, double scale, const glm::vec3& energy) {
  const double r = static_cast<double>(energy.r), g = static_cast<double>(energy.g),
               b = static_cast<double>(energy.b);
  for (int j = 0; j < 4; ++j) {
    for (int o = 0; o < 3; ++o) {
      const int bin = kb[j] + o;
      if (bin >= bins || (j > 0 && bin <= kb[j - 1] + 2)) continue;
      double wi[4];
      for (int i = 0; i < 4; ++i) {
        const int reach = bin - kb[i];
        wi[i] = reach >= 0 && reach <= 2 ? w[reach][i] : 0.0;
      }
      const double value = step ? scale * (wi[0] - wi[3]) : scale * (wi[0] - wi[1] - wi[2] + wi[3]);
      double* entry = diff + static_cast<std::size_t>(bin) * 3;
      entry[0] += value * r;
      entry[1] += value * g;
      entry[2] += value * b;
    }
  }
}

// physics::depositWide where the kernel lies on the axis from bin 2 on and
// is at least a bin wide (depositFootprint's sums of kink weights, not its
// CDF): the four kinks side by side in one vector, the twelve slots in three.
// Returns false, having written nothing, for the kernels it leaves to
// physics::depositWide; else widens [first, last] as widenToWideKernel.
inline bool depositWideAvx2(double* diff, int32_t bins, const glm::vec3& kernel,
                            const glm::vec3& energy, physics::OffAxisSums& lost, int32_t& first,
                            int32_t& last) {
  // footprintKnot: centre + (-halfSum, -halfDiff, halfDiff, halfSum).
  const double wide = static_cast<double>(kernel.y), narrow = static_cast<double>(kernel.z);
  const double halfSum = (wide + narrow) * static_cast<double>(0.5f);
  const double halfDiff = (wide - narrow) * static_cast<double>(0.5f);
  const __m256d knot = _mm256_add_pd(_mm256_set1_pd(static_cast<double>(kernel.x)),
                                     _mm256_setr_pd(-halfSum, -halfDiff, halfDiff, halfSum));
  alignas(32) double knots[4];
  _mm256_store_pd(knots, knot);
  // Not finite, partly before bin 2 (depositFootprint's CDF), narrower than a
  // bin, or wholly past the axis: the scalar deposit's.
  if (!(knots[0] >= 2.0 && knots[3] <= 1e9) || wide < 1.0 ||
      knots[0] >= static_cast<double>(bins)) {
    return false;
  }
  // footprintKnotBin: floor, clamped to [0, bins] (the knots are >= 2).
  const __m128i knotBin =
      _mm256_cvttpd_epi32(_mm256_min_pd(_mm256_floor_pd(knot), _mm256_set1_pd(bins)));
  const bool step = narrow < static_cast<double>(1e-6f);
  const double scale = step ? 1.0 / wide : 1.0 / (wide * narrow);
  // Each kink's weights at its bins knotBin + o: t = (knotBin + o + 1) - knot.
  __m256d weight[3];
  alignas(32) double w[3][4];
  for (int o = 0; o < 3; ++o) {
    const __m256d k1 = _mm256_cvtepi32_pd(_mm_add_epi32(knotBin, _mm_set1_epi32(o + 1)));
    weight[o] = kinkWeight4(_mm256_sub_pd(k1, knot), step);
    _mm256_store_pd(w[o], weight[o]);
  }
  alignas(16) int32_t kb[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(kb), knotBin);
  first = std::min(first, kb[0]);
  last = std::max(last, std::min(kb[3] + 2, bins - 1));
  if (kb[1] > kb[0] + 2 && kb[2] > kb[1] + 2 && kb[3] > kb[2] + 2 && kb[3] + 2 < bins) {
    addApartKinks(diff, kb, weight, step, scale, energy);
  } else {
    addNearKinks(diff, bins, kb, w, step, scale, energy);
  }
  // Nothing before the axis (the first knot is >= 2); after it, 1 - F(bins).
  if (knots[3] >= static_cast<double>(bins)) {
    const double after = physics::footprintMassAfter(kernel, bins);
    if (after > 0.0) lost.after += static_cast<float>(after) * (energy.r + energy.g + energy.b);
  }
  return true;
}

void depositFootprintsAvx2(const VplTerms* terms, const BlockPair* pairs, std::size_t count,
                           int32_t bins, float* histogram, double* diff, physics::OffAxisSums& lost,
                           int32_t& first, int32_t& last) {
  for (std::size_t i = 0; i < count; ++i) {
    const Contribution c = contributionOf(terms, pairs[i]);
    if (c.count == 0) {
      if (!depositWideAvx2(diff, bins, c.kernel, c.energy, lost, first, last)) {
        // SSE code: no AVX state left dirty for it (a transition costs more
        // than the deposit).
        _mm256_zeroupper();
        physics::depositWide(diff, bins, c.kernel, c.energy, lost);
        widenToWideKernel(c.kernel, bins, first, last);
      }
    } else {
      depositNarrowAvx2(histogram, bins, c.kernel, c.shape, c.first, c.count, c.energy, lost);
    }
  }
}

void depositNarrowKernelAvx2(float* histogram, int32_t bins, const glm::vec3& kernel, int32_t first,
                             int32_t count, const glm::vec3& energy, physics::OffAxisSums& lost) {
  depositNarrowAvx2(histogram, bins, kernel, narrowShapeOf(kernel), first, count, energy, lost);
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
