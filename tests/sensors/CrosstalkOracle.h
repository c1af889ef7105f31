#pragma once
// The exact law of a small synchronous SPAD array with prompt crosstalk,
// simulated cycle by cycle and avalanche by avalanche: the oracle of the
// fast path's first-order crosstalk (SpadCrosstalk.h). Obviously right
// rather than fast: every pixel's first photon of the cycle is drawn, then
// the avalanches are taken in time order; each one triggers each neighbour
// that has not fired yet with probability p, in the same bin (prompt), and
// a triggered pixel fires then unless it fired before; a pixel is dead for
// the rest of the cycle after it fires, and its first avalanche is its TDC
// stop. Chains (A -> B -> C) and back-triggering (A -> B suppressing A's own
// later photon) are included: exactly what first order leaves out.
// With `recharges` the detector keeps running instead (the SPAD model's
// engine): live again from the bin after each avalanche, its later
// avalanches in the cycle not recorded (one stop) but triggering its
// neighbours like the first (the exact array driver, SpadArrayEvents.h).

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "support/ChiSquare.h"
#include "tofsim/sensors/Random.h"

namespace tofsim::sensors::test {

struct ArrayOracle {
  int32_t width = 0, height = 0, bins = 0;
  bool eightNeighbours = false;
  double probability = 0.0;
  std::vector<std::vector<double>> flux;  ///< per pixel (y * width + x), per bin
  bool recharges = false;

  /// Histograms per pixel after `cycles` cycles.
  std::vector<std::vector<double>> run(int64_t cycles, uint64_t seed) const {
    const std::size_t n = flux.size();
    std::vector<std::vector<double>> cumulative(n, std::vector<double>(bins + 1, 0.0));
    for (std::size_t k = 0; k < n; ++k)
      for (int32_t i = 0; i < bins; ++i) cumulative[k][i + 1] = cumulative[k][i] + flux[k][i];
    std::vector<std::vector<double>> h(n, std::vector<double>(bins, 0.0));
    Rng rng(seed, 1);
    std::vector<int32_t> when(n), fired(n), liveFrom(n), stopped(n);
    // The first bin >= from where pixel k's flux from `from` passes an Exp(1) draw.
    const auto photon = [&](std::size_t k, int32_t from) {
      const double e = -std::log1p(-rng.uniform());
      int32_t i = from;
      while (i < bins && cumulative[k][i + 1] - cumulative[k][from] < e) ++i;
      return i;
    };
    for (int64_t c = 0; c < cycles; ++c) {
      // Each pixel's first photon: the first bin where the cumulative flux
      // passes an Exp(1) draw (bins: none this cycle).
      for (std::size_t k = 0; k < n; ++k) {
        const double e = -std::log1p(-rng.uniform());
        int32_t i = 0;
        while (i < bins && cumulative[k][i + 1] < e) ++i;
        when[k] = i;
        fired[k] = 0;
        liveFrom[k] = 0;
        stopped[k] = 0;
      }
      // Avalanches in time order: the earliest pending pixel fires and may
      // trigger its live neighbours in the same bin.
      for (;;) {
        std::size_t next = n;
        for (std::size_t k = 0; k < n; ++k)
          if (!fired[k] && when[k] < bins && (next == n || when[k] < when[next])) next = k;
        if (next == n) break;
        const int32_t b = when[next];
        if (!stopped[next]) h[next][b] += 1.0;
        stopped[next] = 1;
        if (recharges) {
          liveFrom[next] = b + 1;
          when[next] = b + 1 < bins ? photon(next, b + 1) : bins;
        } else {
          fired[next] = 1;
        }
        const auto y = static_cast<int32_t>(next) / width, x = static_cast<int32_t>(next) % width;
        for (int32_t dy = -1; dy <= 1; ++dy) {
          for (int32_t dx = -1; dx <= 1; ++dx) {
            if ((dy == 0 && dx == 0) || (!eightNeighbours && dy != 0 && dx != 0)) continue;
            if (y + dy < 0 || y + dy >= height || x + dx < 0 || x + dx >= width) continue;
            const std::size_t j = static_cast<std::size_t>((y + dy) * width + x + dx);
            const bool live = recharges ? liveFrom[j] <= b : !fired[j];
            if (!live || rng.uniform() >= probability) continue;
            if (when[j] > b) when[j] = b;
          }
        }
      }
    }
    return h;
  }
};

/// A lit pixel of the oracle's 3 x 3 tests: a return of 12 bins at a time
/// and height of its own, over a background floor (float values, as a
/// volume holds them).
inline std::vector<double> litPixel(int32_t y, int32_t x, int32_t bins) {
  std::vector<double> f(bins, 0.0);
  const int32_t start = 4 + 3 * ((x + 2 * y) % 4);
  const double height = 0.02 + 0.05 * ((y * 3 + x) % 5);
  for (int32_t t = start; t < start + 12; ++t) f[t] = static_cast<float>(height);
  for (double& v : f) v += static_cast<float>(0.002);  // a background floor
  return f;
}

/// Two-sample chi-square of histograms, summed over pixels.
struct TwoSample {
  double statistic = 0.0;
  int dof = 0;
};

/// Adds to `out` the two-sample statistic of a and b (each over `cycles`
/// cycles), the cycles without a count as one more cell, cells merged to
/// >= 20 counts.
inline void addTwoSample(const std::vector<double>& a, const std::vector<double>& b, double cycles,
                         TwoSample& out) {
  std::vector<double> x = a, y = b;
  double sa = 0.0, sb = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sa += a[i], sb += b[i];
  x.push_back(cycles - sa);
  y.push_back(cycles - sb);
  double cx = 0.0, cy = 0.0;
  int cells = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    cx += x[i];
    cy += y[i];
    if (cx + cy < 20.0 && i + 1 < x.size()) continue;
    if (cx + cy > 0.0) {
      out.statistic += (cx - cy) * (cx - cy) / (cx + cy);
      ++cells;
    }
    cx = cy = 0.0;
  }
  out.dof += cells - 1;
}

// Pearson's statistic of `h` (the sum of `draws` multinomial draws) against
// cell probabilities `law`, the draws that counted nothing as one more cell.
inline tofsim::test::ChiSquare againstMultinomial(std::vector<double> h,
                                                  const std::vector<double>& law, double draws) {
  std::vector<double> expected(law.size());
  double none = 1.0, counted = 0.0;
  for (std::size_t t = 0; t < law.size(); ++t) {
    expected[t] = draws * law[t];
    none -= law[t];
    counted += h[t];
  }
  h.push_back(draws - counted);
  expected.push_back(draws * none);
  return tofsim::test::pearson(h, expected);
}

}  // namespace tofsim::sensors::test
