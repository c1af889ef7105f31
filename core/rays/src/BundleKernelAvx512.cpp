// The bundle kernels for AVX-512 (compiled with -mavx512f -mavx512vl ...:
// core/rays/CMakeLists.txt), run only where the CPU has them and Embree
// runs its AVX-512 kernels: 16 rays a vector; the reciprocal is
// _mm512_rcp14_ps, as Embree's vfloat4 rcp (_mm_rcp14_ps with AVX512VL)
// then its fused Newton step.

#include <immintrin.h>

#include "PlueckerLanes.h"

namespace tofsim::rays::detail {
namespace {

struct Lanes512 {
  static constexpr int W = 16;
  using F = __m512;
  using M = __mmask16;
  static F load(const float* p) { return _mm512_load_ps(p); }
  static void store(float* p, F a) { _mm512_store_ps(p, a); }
  static F set(float x) { return _mm512_set1_ps(x); }
  static F add(F a, F b) { return _mm512_add_ps(a, b); }
  static F mul(F a, F b) { return _mm512_mul_ps(a, b); }
  static F fma(F a, F b, F c) { return _mm512_fmadd_ps(a, b, c); }
  static F min(F a, F b) { return _mm512_min_ps(a, b); }
  static F max(F a, F b) { return _mm512_max_ps(a, b); }
  static F abs(F a) { return _mm512_abs_ps(a); }
  static F neg(F a) { return _mm512_sub_ps(_mm512_setzero_ps(), a); }
  static F rcp(F a) {
    const F r = _mm512_rcp14_ps(a);
    return _mm512_fmadd_ps(r, _mm512_fnmadd_ps(a, r, _mm512_set1_ps(1.0f)), r);
  }
  static M ge(F a, F b) { return _mm512_cmp_ps_mask(a, b, _CMP_GE_OQ); }
  static M le(F a, F b) { return _mm512_cmp_ps_mask(a, b, _CMP_LE_OQ); }
  static M lt(F a, F b) { return _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ); }
  static M eq(F a, F b) { return _mm512_cmp_ps_mask(a, b, _CMP_EQ_OQ); }
  static M neq(F a, F b) { return _mm512_cmp_ps_mask(a, b, _CMP_NEQ_UQ); }
  static M andm(M a, M b) { return static_cast<M>(a & b); }
  static M orm(M a, M b) { return static_cast<M>(a | b); }
  static bool any(M a) { return a != 0; }
  static F blend(M m, F a, F b) { return _mm512_mask_blend_ps(m, b, a); }
  static M loadMask(const int32_t* p) {
    return _mm512_cmpneq_epi32_mask(_mm512_load_si512(p), _mm512_setzero_si512());
  }
  static M loadHitMask(const int32_t* p) {
    return _mm512_cmpge_epi32_mask(_mm512_load_si512(p), _mm512_setzero_si512());
  }
  static void storeHit(int32_t* p, M closer, int32_t index) {
    _mm512_mask_store_epi32(p, closer, _mm512_set1_epi32(index));
  }
  static void storeTie(int32_t* p, M closer, M same) {
    const __m512i tie = _mm512_load_si512(p);
    const __m512i kept = _mm512_mask_mov_epi32(tie, closer, _mm512_setzero_si512());
    _mm512_store_si512(p, _mm512_mask_mov_epi32(kept, same, _mm512_set1_epi32(1)));
  }
};

}  // namespace

void intersectAvx512(BundleRays& rays, const BundleTriangle* triangles, const int32_t* indices,
                     int count) {
  intersectLanes<Lanes512>(rays, triangles, indices, count);
}

void finishAvx512(BundleRays& rays) { finishLanes<Lanes512>(rays); }

}  // namespace tofsim::rays::detail
