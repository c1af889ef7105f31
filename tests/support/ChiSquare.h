#pragma once
// Pearson's chi-square of observed counts against expected ones, and its
// quantiles, for the statistical tests of the random draws.

#include <cmath>
#include <vector>

namespace tofsim::test {

/// The chi-square statistic with its degrees of freedom (cells - 1).
struct ChiSquare {
  double statistic = 0.0;
  int dof = 0;
};

/// Pearson's statistic over cells of consecutive entries, each cell merged
/// until its expected count reaches `minExpected` (the last one joins the
/// cell before it if short); `expected` sums to the number of draws.
inline ChiSquare pearson(const std::vector<double>& observed, const std::vector<double>& expected,
                         double minExpected = 5.0) {
  std::vector<double> obs, exp;
  double o = 0.0, e = 0.0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    o += observed[i];
    e += expected[i];
    if (e >= minExpected) {
      obs.push_back(o);
      exp.push_back(e);
      o = e = 0.0;
    }
  }
  if (!exp.empty()) {
    obs.back() += o;
    exp.back() += e;
  }
  ChiSquare c;
  for (std::size_t i = 0; i < exp.size(); ++i) {
    c.statistic += (obs[i] - exp[i]) * (obs[i] - exp[i]) / exp[i];
  }
  c.dof = static_cast<int>(exp.size()) - 1;
  return c;
}

/// The chi-square quantile at the standard normal quantile z (Wilson and
/// Hilferty 1931; within 1 % of the exact value for dof >= 10): z = 3.09
/// gives the upper 0.001 quantile, z = -3.09 the lower.
inline double chiSquareQuantile(int dof, double z) {
  const double k = static_cast<double>(dof);
  const double a = 2.0 / (9.0 * k);
  return k * std::pow(1.0 - a + z * std::sqrt(a), 3.0);
}

}  // namespace tofsim::test
