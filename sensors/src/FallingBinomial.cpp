#include "FallingBinomial.h"

#include <algorithm>
#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

namespace {
constexpr double kMaxMean = 32.0;         // longer CDF tables cost more to build than they save
constexpr std::size_t kMaxTable = 192;    // entries: P(X >= 192) < 1e-40 for means <= 32
constexpr double kTailPmf = 1e-20;        // past the mean, the table stops below this pmf
constexpr double kAboveMean = 0.1;        // n - n0 <= this / q: the extra trials rarely count
constexpr uint64_t kMaxSlack = 2048;      // powers of (1 - q) kept
constexpr double kDrawsPerRebuild = 8.0;  // n may fall by n q per draw

uint64_t slackFor(double q) {
  return static_cast<uint64_t>(std::min(static_cast<double>(kMaxSlack), kAboveMean / q));
}
}  // namespace

bool FallingBinomial::suits(uint64_t n, double q) {
  const double mean = static_cast<double>(n) * q;
  return q > 0.0 && q <= 0.5 && mean <= kMaxMean &&
         static_cast<double>(slackFor(q)) >= kDrawsPerRebuild * mean;
}

void FallingBinomial::reset(double q) {
  TOFSIM_CHECK(q > 0.0 && q <= 0.5);
  built_ = false;
  if (q == q_) return;
  q_ = q;
  s_ = q / (1.0 - q);
  log1mq_ = std::log1p(-q);
  slack_ = slackFor(q);
}

void FallingBinomial::rebuild(uint64_t n) {
  n0_ = n - std::min(n, slack_);
  // Binomial(n0, q)'s pmf by its ratio P(k) / P(k - 1) = (n0 - k + 1) / k * q / (1 - q).
  const double mean = static_cast<double>(n0_) * q_;
  double pmf = std::exp(static_cast<double>(n0_) * log1mq_), sum = pmf;
  cdf_.assign(1, sum);
  for (uint64_t k = 1; k <= n0_ && cdf_.size() < kMaxTable; ++k) {
    if (static_cast<double>(k) > mean && pmf < kTailPmf) break;
    pmf *= static_cast<double>(n0_ - k + 1) / static_cast<double>(k) * s_;
    sum += pmf;
    cdf_.push_back(sum);
  }
  lastPmf_ = pmf;
  // guide_[j] = k for the j with cdf_[k - 1] <= j / kGuide < cdf_[k], i.e.
  // j < cdf_[k] kGuide (exact: kGuide is a power of 2); the rest the last k.
  std::size_t j = 0;
  for (std::size_t k = 0; k < cdf_.size() && j < kGuide; ++k) {
    const auto end = static_cast<std::size_t>(
        std::min(static_cast<double>(kGuide), std::ceil(cdf_[k] * static_cast<double>(kGuide))));
    if (end > j) {
      std::fill(guide_.begin() + j, guide_.begin() + end, static_cast<uint16_t>(k));
      j = end;
    }
  }
  std::fill(guide_.begin() + j, guide_.end(), static_cast<uint16_t>(cdf_.size() - 1));
  if (powersQ_ != q_) {
    powers_.resize(static_cast<std::size_t>(slack_) + 1);
    const double factor = std::exp(log1mq_);
    double w = 1.0;
    for (double& pw : powers_) {
      pw = w;
      w *= factor;
    }
    powersQ_ = q_;
  }
  built_ = true;
}

// The smallest k with u < P(X <= k), u = Rng::uniform()'s 53 bits; past the
// table, the pmf's recursion goes on. The high 27 bits put u in
// [uLo, uLo + 2^-27): unless a CDF value falls in there (rarely), they decide
// k alone and the low 26 bits are never drawn (a generator step saved).
uint64_t FallingBinomial::drawBase(Rng& rng) const {
  const uint64_t hi = rng.nextU32() >> 5;
  const double uLo = static_cast<double>(hi) * 0x1.0p-27;
  std::size_t k = guide_[hi >> (27 - kGuideBits)];  // floor(u kGuide)
  while (k + 1 < cdf_.size() && cdf_[k] <= uLo) ++k;
  if (cdf_[k] >= uLo + 0x1.0p-27) return k;  // cdf_[k - 1] <= uLo <= u < cdf_[k]
  const double u = static_cast<double>((hi << 26) | (rng.nextU32() >> 6)) * 0x1.0p-53;
  while (k + 1 < cdf_.size() && cdf_[k] <= u) ++k;
  if (cdf_[k] > u) return k;
  double pmf = lastPmf_, sum = cdf_[k];
  uint64_t x = k;
  while (sum <= u && x < n0_) {
    ++x;
    pmf *= static_cast<double>(n0_ - x + 1) / static_cast<double>(x) * s_;
    if (pmf <= 0.0) break;  // u lost to rounding in the far tail
    sum += pmf;
  }
  return x;
}

// Binomial(m, q) for the m <= slack trials above n0, by inversion from 0.
uint64_t FallingBinomial::drawAbove(uint64_t m, Rng& rng) const {
  double r = powers_[m];
  double u = rng.uniformUnless(r);
  if (u < 0.0) return 0;
  uint64_t x = 0;
  const double a = (static_cast<double>(m) + 1.0) * s_;
  while (u >= r && x < m) {
    u -= r;
    ++x;
    r *= a / static_cast<double>(x) - s_;
    if (r <= 0.0) break;
  }
  return x;
}

uint64_t FallingBinomial::draw(uint64_t n, Rng& rng) {
  if (!built_ || n < n0_ || n - n0_ > slack_) rebuild(n);
  const uint64_t m = n - n0_;
  const uint64_t x = drawBase(rng);
  return m == 0 ? x : x + drawAbove(m, rng);
}

}  // namespace tofsim::sensors::detail
