#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tofsim/sensors/Random.h"

namespace tofsim::sensors {
namespace {

struct Moments {
  double mean = 0.0;
  double variance = 0.0;
};

template <typename Draw>
Moments moments(int n, Draw draw) {
  double s = 0.0, s2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = draw();
    s += v;
    s2 += v * v;
  }
  Moments m;
  m.mean = s / n;
  m.variance = (s2 - s * s / n) / (n - 1);
  return m;
}

TEST(RandomTest, SameSeedAndStreamGiveSameSequence) {
  Rng a(42, 7), b(42, 7), c(42, 8), d(43, 7);
  int sameC = 0, sameD = 0;
  for (int i = 0; i < 100; ++i) {
    const uint32_t va = a.nextU32();
    EXPECT_EQ(va, b.nextU32());
    sameC += va == c.nextU32();
    sameD += va == d.nextU32();
  }
  EXPECT_LT(sameC, 3);
  EXPECT_LT(sameD, 3);
}

TEST(RandomTest, UniformAndNormalMoments) {
  Rng rng(1, 0);
  const int n = 100000;
  const Moments u = moments(n, [&] { return rng.uniform(); });
  EXPECT_NEAR(u.mean, 0.5, 4.0 * std::sqrt(1.0 / 12.0 / n));
  EXPECT_NEAR(u.variance, 1.0 / 12.0, 0.002);
  const Moments g = moments(n, [&] { return rng.normal(); });
  EXPECT_NEAR(g.mean, 0.0, 4.0 / std::sqrt(n));
  EXPECT_NEAR(g.variance, 1.0, 4.0 * std::sqrt(2.0 / n));
}

TEST(RandomTest, PoissonMeanEqualsVariance) {
  Rng rng(2, 0);
  const int n = 40000;
  for (double mean : {0.3, 5.0, 11.9, 12.0, 80.0, 5000.0}) {
    const Moments m = moments(n, [&] { return static_cast<double>(rng.poisson(mean)); });
    EXPECT_NEAR(m.mean, mean, 4.0 * std::sqrt(mean / n)) << "mean " << mean;
    // Var(s^2) ~ (mu + 2 mu^2) / n for a Poisson.
    EXPECT_NEAR(m.variance, mean, 4.0 * std::sqrt((mean + 2.0 * mean * mean) / n)) << mean;
  }
}

TEST(RandomTest, BinomialMomentsIncludingBetaSplitting) {
  Rng rng(3, 0);
  const int n = 20000;
  const std::vector<std::pair<uint64_t, double>> cases = {
      {10, 0.3}, {1000, 0.001}, {1000, 0.5}, {1000000, 0.3}, {1000000, 0.99999}, {200, 0.97}};
  for (const auto& [trials, p] : cases) {
    const double mean = trials * p, var = trials * p * (1.0 - p);
    const Moments m = moments(n, [&] { return static_cast<double>(rng.binomial(trials, p)); });
    EXPECT_NEAR(m.mean, mean, 4.0 * std::sqrt(var / n)) << trials << " " << p;
    EXPECT_NEAR(m.variance, var, 4.0 * std::sqrt(2.0 * var * var / n + var / n))
        << trials << " " << p;
  }
  EXPECT_EQ(rng.binomial(0, 0.5), 0u);
  EXPECT_EQ(rng.binomial(17, 1.0), 17u);
  EXPECT_EQ(rng.binomial(17, 0.0), 0u);
}

}  // namespace
}  // namespace tofsim::sensors
