#include "KernelCorrelation.h"

#include <algorithm>
#include <cstring>

#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

namespace {

// Two doubles (an SSE2 register) and four (an AVX one): GCC and Clang lower
// the types to what the target has. The compilers vectorised the blocks'
// loops along j, with scalar sums: spelt out here. Each lane is its own
// tau's sum, so the lanes' grouping changes no bit: every version gives the
// same doubles.
using Pair = double __attribute__((vector_size(16)));
using Quad = double __attribute__((vector_size(32)));
constexpr int32_t kMaxBlock = 16;  // arrival bins summed together, at most

// By reference: a vector passed or returned by value has an ABI of its own.
template <typename V>
__attribute__((always_inline)) inline void load(V& v, const double* p) {
  std::memcpy(&v, p, sizeof v);
}

// Every tau: the sums of a block of Vectors x lanes taus kept in registers
// (2 Vectors independent sums of a and b: enough to hide the additions'
// latency), j the outer loop, the block's bins of h the inner one, a vector
// at a time. hp[x + pad] = h[x], zero outside. Inlined always: compiled for
// its caller's target (blocksAvx2's).
template <typename V, int32_t Vectors>
__attribute__((always_inline)) inline void blocks(const double* hp, int32_t pad, int32_t K,
                                                  int32_t first, const double* a, const double* b,
                                                  int32_t L, double* ca, double* cb) {
  constexpr auto lanes = static_cast<int32_t>(sizeof(V) / sizeof(double));
  constexpr int32_t block = lanes * Vectors;
  static_assert(block <= kMaxBlock);
  for (int32_t tau0 = 0; tau0 < K; tau0 += block) {
    V sa[Vectors] = {}, sb[Vectors] = {};
    const double* x = hp + pad + tau0 + first;
    for (int32_t j = 0; j < L; ++j) {
      const double aj = a[j], bj = b[j];
      for (int32_t t = 0; t < Vectors; ++t) {
        V xt;
        load(xt, x + j + lanes * t);
        sa[t] += xt * aj;
        sb[t] += xt * bj;
      }
    }
    for (int32_t t = 0; t < block && tau0 + t < K; ++t) {
      ca[tau0 + t] = sa[t / lanes][t % lanes];
      cb[tau0 + t] = sb[t / lanes][t % lanes];
    }
  }
}

// x86-64 with GCC or Clang: a version for AVX2 CPUs (16 taus a block, in 8
// registers of 4), chosen at run time; no FMA, so products and sums are
// rounded one by one as in the default version (8 taus, in 8 SSE2 registers).
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
__attribute__((target("avx2"))) void blocksAvx2(const double* hp, int32_t pad, int32_t K,
                                                int32_t first, const double* a, const double* b,
                                                int32_t L, double* ca, double* cb) {
  blocks<Quad, 4>(hp, pad, K, first, a, b, L, ca, cb);
}
bool hasAvx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}
#endif

void correlateBlocks(const double* hp, int32_t pad, int32_t K, int32_t first, const double* a,
                     const double* b, int32_t L, double* ca, double* cb, bool portable) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  if (!portable && hasAvx2()) return blocksAvx2(hp, pad, K, first, a, b, L, ca, cb);
#endif
  blocks<Pair, 4>(hp, pad, K, first, a, b, L, ca, cb);
}

// From each counted bin i: its terms to tau = i - first - j, in a forward run
// over the reversed kernels ar, br (no branch inside, vectorised).
void scatter(const std::vector<double>& h, int32_t first, const double* ar, const double* br,
             int32_t L, double* ca, double* cb) {
  const auto K = static_cast<int32_t>(h.size());
  std::fill(ca, ca + K, 0.0);
  std::fill(cb, cb + K, 0.0);
  for (int32_t i = 0; i < K; ++i) {
    const double hi = h[i];
    if (hi == 0.0) continue;
    const int32_t tau0 = i - first - (L - 1);  // ar[r] = a[L - 1 - r] goes to tau0 + r
    const int32_t rBegin = std::max(0, -tau0), rEnd = std::min(L, K - tau0);
    for (int32_t r = rBegin; r < rEnd; ++r) {
      ca[tau0 + r] += hi * ar[r];
      cb[tau0 + r] += hi * br[r];
    }
  }
}

}  // namespace

void correlateWithTwo(const std::vector<double>& h, int32_t first, const std::vector<double>& a,
                      const std::vector<double>& b, std::vector<double>& ca,
                      std::vector<double>& cb, std::vector<double>& padded, bool portable) {
  TOFSIM_CHECK(!a.empty() && a.size() == b.size());
  const auto K = static_cast<int32_t>(h.size());
  const auto L = static_cast<int32_t>(a.size());
  ca.resize(h.size());
  cb.resize(h.size());
  int32_t counted = 0;
  for (double v : h) counted += v != 0.0 ? 1 : 0;
  // The blocks cost K L whatever h is; the scatter about twice that per
  // counted bin (a load and a store per term).
  if (2 * counted < K) {
    padded.resize(2 * a.size());
    for (int32_t j = 0; j < L; ++j) {
      padded[L - 1 - j] = a[j];
      padded[2 * L - 1 - j] = b[j];
    }
    scatter(h, first, padded.data(), padded.data() + L, L, ca.data(), cb.data());
    return;
  }
  // hp covers every index tau + first + j of the blocks: tau in [0, K
  // rounded up to a block), j in [0, L).
  const int32_t pad = std::max(0, -first);
  const int32_t rounded = (K + kMaxBlock - 1) / kMaxBlock * kMaxBlock;
  const int32_t size = pad + std::max(K, rounded + first + L);
  padded.assign(static_cast<std::size_t>(size), 0.0);
  std::copy(h.begin(), h.end(), padded.begin() + pad);
  correlateBlocks(padded.data(), pad, K, first, a.data(), b.data(), L, ca.data(), cb.data(),
                  portable);
}

}  // namespace tofsim::sensors::detail
