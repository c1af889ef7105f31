#pragma once
// Private to the SPAD model: O(1) binomial draws along a run of bins of one
// flux, where the number of trials (cycles still without a detection) falls
// a little from bin to bin.

#include <array>
#include <cstdint>
#include <vector>

#include "tofsim/sensors/Random.h"

namespace tofsim::sensors::detail {

/// Binomial(n, q) for one q and a falling n, as the sum of two independent
/// binomials: Binomial(n0, q) from a CDF table with a guide table (n0 <= n a
/// base kept while n stays within `slack` above it) and Binomial(n - n0, q),
/// which is 0 with probability (1 - q)^(n - n0) from a table of powers.
/// Exact in law (the sum is Binomial(n, q)); the tables depend only on q and
/// n0, and n0 only on the draws since reset(), so the draws are a function of
/// the random stream.
class FallingBinomial {
 public:
  /// Whether draws at n trials of probability q are O(1) here: a short CDF
  /// table, and n falling by about n q per draw rebuilds it rarely.
  static bool suits(uint64_t n, double q);
  /// Starts a run of probability q in (0, 0.5]; forgets the base n0.
  void reset(double q);
  uint64_t draw(uint64_t n, Rng& rng);

 private:
  static constexpr int kGuideBits = 8;  // a power of 2: j / kGuide is exact
  static constexpr std::size_t kGuide = std::size_t{1} << kGuideBits;
  void rebuild(uint64_t n);
  uint64_t drawBase(Rng& rng) const;
  uint64_t drawAbove(uint64_t m, Rng& rng) const;

  double q_ = -1.0, s_ = 0.0, log1mq_ = 0.0;
  uint64_t slack_ = 0, n0_ = 0;
  bool built_ = false;
  std::vector<double> cdf_;               ///< P(X <= k), X ~ Binomial(n0, q), k < cdf_.size()
  double lastPmf_ = 0.0;                  ///< P(X = cdf_.size() - 1), to continue past the table
  std::array<uint16_t, kGuide> guide_{};  ///< first k with cdf_[k] > j / kGuide
  std::vector<double> powers_;            ///< (1 - q)^m, m = 0 .. slack_
  double powersQ_ = -1.0;                 ///< the q of powers_ (kept across resets)
};

}  // namespace tofsim::sensors::detail
