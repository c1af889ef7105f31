// The bundle kernels for AVX2 + FMA (compiled with -mavx2 -mfma:
// core/rays/CMakeLists.txt), where Embree runs its AVX2 kernels: 8 rays a
// vector; the reciprocal is _mm256_rcp_ps, as Embree's vfloat4 rcp
// (_mm_rcp_ps without AVX512VL) then its fused Newton step.

#include <immintrin.h>

#include "PlueckerLanes.h"

namespace tofsim::rays::detail {
namespace {

struct Lanes256 {
  static constexpr int W = 8;
  using F = __m256;
  using M = __m256;  // all ones where true
  static F load(const float* p) { return _mm256_load_ps(p); }
  static void store(float* p, F a) { _mm256_store_ps(p, a); }
  static F set(float x) { return _mm256_set1_ps(x); }
  static F add(F a, F b) { return _mm256_add_ps(a, b); }
  static F mul(F a, F b) { return _mm256_mul_ps(a, b); }
  static F fma(F a, F b, F c) { return _mm256_fmadd_ps(a, b, c); }
  static F min(F a, F b) { return _mm256_min_ps(a, b); }
  static F max(F a, F b) { return _mm256_max_ps(a, b); }
  static F abs(F a) { return _mm256_and_ps(a, _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff))); }
  static F neg(F a) { return _mm256_sub_ps(_mm256_setzero_ps(), a); }
  static F rcp(F a) {
    const F r = _mm256_rcp_ps(a);
    return _mm256_fmadd_ps(r, _mm256_fnmadd_ps(a, r, _mm256_set1_ps(1.0f)), r);
  }
  static M ge(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_GE_OQ); }
  static M le(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_LE_OQ); }
  static M lt(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_LT_OQ); }
  static M eq(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_EQ_OQ); }
  static M neq(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_NEQ_UQ); }
  static M andm(M a, M b) { return _mm256_and_ps(a, b); }
  static M orm(M a, M b) { return _mm256_or_ps(a, b); }
  static bool any(M a) { return _mm256_movemask_ps(a) != 0; }
  static F blend(M m, F a, F b) { return _mm256_blendv_ps(b, a, m); }
  static M loadMask(const int32_t* p) {
    const __m256i v = _mm256_load_si256(reinterpret_cast<const __m256i*>(p));
    return _mm256_castsi256_ps(
        _mm256_xor_si256(_mm256_cmpeq_epi32(v, _mm256_setzero_si256()), _mm256_set1_epi32(-1)));
  }
  static M loadHitMask(const int32_t* p) {
    const __m256i v = _mm256_load_si256(reinterpret_cast<const __m256i*>(p));
    return _mm256_castsi256_ps(_mm256_cmpgt_epi32(v, _mm256_set1_epi32(-1)));
  }
  static void storeHit(int32_t* p, M closer, int32_t index) {
    auto* q = reinterpret_cast<__m256i*>(p);
    const __m256 old = _mm256_castsi256_ps(_mm256_load_si256(q));
    _mm256_store_si256(q, _mm256_castps_si256(_mm256_blendv_ps(
                              old, _mm256_castsi256_ps(_mm256_set1_epi32(index)), closer)));
  }
  static void storeTie(int32_t* p, M closer, M same) {
    auto* q = reinterpret_cast<__m256i*>(p);
    const __m256 tie = _mm256_castsi256_ps(_mm256_load_si256(q));
    const __m256 kept = _mm256_andnot_ps(closer, tie);
    const __m256 one = _mm256_castsi256_ps(_mm256_set1_epi32(1));
    _mm256_store_si256(q, _mm256_castps_si256(_mm256_blendv_ps(kept, one, same)));
  }
};

}  // namespace

void intersectAvx2(BundleRays& rays, const BundleTriangle* triangles, const int32_t* indices,
                   int count) {
  intersectLanes<Lanes256>(rays, triangles, indices, count);
}

void finishAvx2(BundleRays& rays) { finishLanes<Lanes256>(rays); }

}  // namespace tofsim::rays::detail
