#pragma once
// Comparing one pixel's time histograms by shape: sums, the L1 distance
// between histograms normalised to unit sum (0 = the same shape, 2 =
// disjoint), and the median of per-pixel figures. Shared by the footprint
// tests (tests/physics, tests/render).

#include <algorithm>
#include <cmath>
#include <vector>

namespace tofsim::test {

inline double histogramSum(const std::vector<double>& h) {
  double s = 0.0;
  for (double v : h) s += v;
  return s;
}

inline double normalisedL1(const std::vector<double>& p, const std::vector<double>& q) {
  const double sp = histogramSum(p), sq = histogramSum(q);
  double l1 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) l1 += std::abs(p[i] / sp - q[i] / sq);
  return l1;
}

inline double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace tofsim::test
