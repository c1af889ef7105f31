// The SPAD's private FallingBinomial (sensors/src): draws along a falling
// number of trials against Binomial(n, q), through the randomised
// probability integral transform (uniform exactly when each draw follows its
// own law) and the sum of the draws.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "FallingBinomial.h"
#include "support/ChiSquare.h"

namespace tofsim::sensors::detail {
namespace {

// P(X < k) and P(X <= k) for X ~ Binomial(n, q), by the pmf's recursion.
std::pair<double, double> binomialCdfPair(uint64_t n, double q, uint64_t k) {
  double pmf = std::exp(static_cast<double>(n) * std::log1p(-q)), below = 0.0;
  for (uint64_t j = 0; j < k; ++j) {
    below += pmf;
    pmf *= static_cast<double>(n - j) / static_cast<double>(j + 1) * q / (1.0 - q);
  }
  return {below, below + pmf};
}

struct Check {
  tofsim::test::ChiSquare pit;  ///< of the transformed draws in 100 cells
  double meanZ = 0.0;           ///< (sum of draws - sum of n q) / its standard deviation
};

// Runs of `run` draws from n0 trials, n falling by each draw (as the SPAD's
// cycles without a detection), `runs` times; draws checked against `qLaw`.
Check fallingDraws(uint64_t n0, double q, double qLaw, int run, int runs) {
  FallingBinomial falling;
  Rng rng(11, 3), pit(12, 3);
  std::vector<double> cells(100, 0.0);
  double sum = 0.0, mean = 0.0, variance = 0.0;
  for (int r = 0; r < runs; ++r) {
    falling.reset(q);
    uint64_t n = n0;
    for (int i = 0; i < run && FallingBinomial::suits(n, q); ++i) {
      const uint64_t k = falling.draw(n, rng);
      const auto [lo, hi] = binomialCdfPair(n, qLaw, k);
      const double u = lo + pit.uniform() * (hi - lo);
      cells[std::min<std::size_t>(99, static_cast<std::size_t>(u * 100.0))] += 1.0;
      sum += static_cast<double>(k);
      mean += static_cast<double>(n) * qLaw;
      variance += static_cast<double>(n) * qLaw * (1.0 - qLaw);
      n -= k;
    }
  }
  double total = 0.0;
  for (const double c : cells) total += c;
  Check check;
  check.pit = tofsim::test::pearson(cells, std::vector<double>(100, total / 100.0));
  check.meanZ = (sum - mean) / std::sqrt(variance);
  return check;
}

// The SPAD's ambient floor (n q ~ 6, slack capped at 2048 trials), a floor
// whose slack is 0.1 / q (n q ~ 3), and n q ~ 30: several table rebuilds per
// run, draws above the base n0 included.
TEST(FallingBinomialTest, DrawsFollowBinomialAsTrialsFall) {
  for (const auto& [n0, q] :
       std::vector<std::pair<uint64_t, double>>{{100000, 6e-5}, {3000, 1e-3}, {300000, 1e-4}}) {
    const Check c = fallingDraws(n0, q, q, 2000, 300);
    EXPECT_LT(c.pit.statistic, tofsim::test::chiSquareQuantile(c.pit.dof, 3.09)) << q;
    EXPECT_GT(c.pit.statistic, tofsim::test::chiSquareQuantile(c.pit.dof, -3.09)) << q;
    EXPECT_LT(std::fabs(c.meanZ), 4.0) << q;
  }
}

// The checks can fail: draws of q told from a law of q (1 + 0.5 %).
TEST(FallingBinomialTest, ChecksRejectAHalfPercentDistortion) {
  const Check c = fallingDraws(100000, 6e-5, 6e-5 * 1.005, 2000, 300);
  EXPECT_GT(std::fabs(c.meanZ), 5.0);
}

TEST(FallingBinomialTest, SuitsOnlyShortTablesAndRareRebuilds) {
  EXPECT_TRUE(FallingBinomial::suits(100000, 6e-5));
  EXPECT_FALSE(FallingBinomial::suits(100000, 1e-3));  // n q = 100: BTRS
  EXPECT_FALSE(FallingBinomial::suits(1000, 0.02));    // slack 5 trials: rebuilt every draw
  EXPECT_FALSE(FallingBinomial::suits(100, 0.0));
}

}  // namespace
}  // namespace tofsim::sensors::detail
