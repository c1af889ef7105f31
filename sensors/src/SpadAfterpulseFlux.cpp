#include "SpadAfterpulseFlux.h"

#include <algorithm>
#include <cmath>

#include "tofsim/sensors/Spad.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

namespace {
constexpr int kMaxIterations = 200;
constexpr double kTolerance = 1e-12;

// y_i = sum_{s >= 0} lambda^s x_(i - shift - s), x periodic: the avalanches
// of bin j released s whole bins after the live moment j + shift, folded on
// the cycle. O(B): y_0 summed once over a cycle (the later cycles fold in
// 1 / (1 - lambda^B)), then y_i = x_(i - shift) + lambda y_(i - 1).
void geometricFold(const std::vector<double>& x, int64_t shift, double lambda,
                   std::vector<double>& y) {
  const auto B = static_cast<int64_t>(x.size());
  // The index i - shift - s on the cycle, walked down (y_0) and up (y_i)
  // without a modulo per term.
  const int64_t start = ((-shift % B) + B) % B;  // (0 - shift) mod B
  double y0 = 0.0, power = 1.0;
  for (int64_t s = 0, j = start; s < B; ++s, power *= lambda, j = j == 0 ? B - 1 : j - 1)
    y0 += power * x[j];
  y.assign(x.size(), 0.0);
  y[0] = y0 / (1.0 - power);
  for (int64_t i = 1, j = start + 1 == B ? 0 : start + 1; i < B; ++i, j = j + 1 == B ? 0 : j + 1)
    y[i] = x[j] + lambda * y[i - 1];
}
}  // namespace

std::vector<double> firstOrderAfterpulseFlux(const std::vector<double>& flux, int32_t deadBins,
                                             const AfterpulseLaw& law) {
  TOFSIM_CHECK(!flux.empty() && law.delays_bins.size() == law.weights.size());
  if (!law.on()) return flux;
  double weights = 0.0;
  for (double w : law.weights) weights += w;
  std::vector<double> out = flux, m, y;
  for (int n = 0; n < kMaxIterations; ++n) {
    m = freeRunningProbabilities(out, deadBins);
    std::vector<double> next = flux;
    for (std::size_t c = 0; c < law.delays_bins.size(); ++c) {
      // Released in the k-th whole bin after the live moment: (1 - lambda) lambda^k.
      const double lambda = std::exp(-1.0 / law.delays_bins[c]);
      geometricFold(m, static_cast<int64_t>(deadBins) + 1, lambda, y);
      const double scale = law.mean * law.weights[c] / weights * (1.0 - lambda);
      for (std::size_t i = 0; i < y.size(); ++i) next[i] += scale * y[i];
    }
    double change = 0.0;
    for (std::size_t i = 0; i < out.size(); ++i)
      change = std::max(change, std::fabs(next[i] - out[i]));
    out.swap(next);
    if (change < kTolerance) break;
  }
  return out;
}

}  // namespace tofsim::sensors::detail
