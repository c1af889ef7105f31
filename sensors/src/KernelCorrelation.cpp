#include "KernelCorrelation.h"

#include <algorithm>
#include <cstring>

#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

namespace {

// Two doubles (an SSE2 register; GCC and Clang lower it to scalars where
// there is none). The compilers vectorised the blocks' loops along j, with
// scalar sums: spelt out here.
using Pair = double __attribute__((vector_size(16)));
constexpr int32_t kPairs = 4;
constexpr int32_t kBlock = 2 * kPairs;  // arrival bins summed together

Pair load(const double* p) {
  Pair v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Every tau: the sums of a block of kBlock taus kept in registers, j the
// outer loop, the block's kBlock bins of h the inner one, two at a time.
// hp[x + pad] = h[x], zero outside.
void blocks(const double* hp, int32_t pad, int32_t K, int32_t first, const double* a,
            const double* b, int32_t L, double* ca, double* cb) {
  for (int32_t tau0 = 0; tau0 < K; tau0 += kBlock) {
    Pair sa[kPairs] = {}, sb[kPairs] = {};
    const double* x = hp + pad + tau0 + first;
    for (int32_t j = 0; j < L; ++j) {
      const Pair aj = {a[j], a[j]}, bj = {b[j], b[j]};
      for (int32_t t = 0; t < kPairs; ++t) {
        const Pair xt = load(x + j + 2 * t);
        sa[t] += xt * aj;
        sb[t] += xt * bj;
      }
    }
    for (int32_t t = 0; t < kBlock && tau0 + t < K; ++t) {
      ca[tau0 + t] = sa[t / 2][t % 2];
      cb[tau0 + t] = sb[t / 2][t % 2];
    }
  }
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
                      std::vector<double>& cb, std::vector<double>& padded) {
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
  // rounded up to kBlock), j in [0, L).
  const int32_t pad = std::max(0, -first);
  const int32_t rounded = (K + kBlock - 1) / kBlock * kBlock;
  const int32_t size = pad + std::max(K, rounded + first + L);
  padded.assign(static_cast<std::size_t>(size), 0.0);
  std::copy(h.begin(), h.end(), padded.begin() + pad);
  blocks(padded.data(), pad, K, first, a.data(), b.data(), L, ca.data(), cb.data());
}

}  // namespace tofsim::sensors::detail
