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

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "tofsim/sensors/Random.h"

namespace tofsim::sensors::test {

struct ArrayOracle {
  int32_t width = 0, height = 0, bins = 0;
  bool eightNeighbours = false;
  double probability = 0.0;
  std::vector<std::vector<double>> flux;  ///< per pixel (y * width + x), per bin

  /// Histograms per pixel after `cycles` cycles.
  std::vector<std::vector<double>> run(int64_t cycles, uint64_t seed) const {
    const std::size_t n = flux.size();
    std::vector<std::vector<double>> cumulative(n, std::vector<double>(bins + 1, 0.0));
    for (std::size_t k = 0; k < n; ++k)
      for (int32_t i = 0; i < bins; ++i) cumulative[k][i + 1] = cumulative[k][i] + flux[k][i];
    std::vector<std::vector<double>> h(n, std::vector<double>(bins, 0.0));
    Rng rng(seed, 1);
    std::vector<int32_t> when(n), fired(n);
    for (int64_t c = 0; c < cycles; ++c) {
      // Each pixel's first photon: the first bin where the cumulative flux
      // passes an Exp(1) draw (bins: none this cycle).
      for (std::size_t k = 0; k < n; ++k) {
        const double e = -std::log1p(-rng.uniform());
        int32_t i = 0;
        while (i < bins && cumulative[k][i + 1] < e) ++i;
        when[k] = i;
        fired[k] = 0;
      }
      // Avalanches in time order: the earliest pending pixel fires and may
      // trigger its live neighbours in the same bin.
      for (;;) {
        std::size_t next = n;
        for (std::size_t k = 0; k < n; ++k)
          if (!fired[k] && when[k] < bins && (next == n || when[k] < when[next])) next = k;
        if (next == n) break;
        fired[next] = 1;
        h[next][when[next]] += 1.0;
        const auto y = static_cast<int32_t>(next) / width, x = static_cast<int32_t>(next) % width;
        for (int32_t dy = -1; dy <= 1; ++dy) {
          for (int32_t dx = -1; dx <= 1; ++dx) {
            if ((dy == 0 && dx == 0) || (!eightNeighbours && dy != 0 && dx != 0)) continue;
            if (y + dy < 0 || y + dy >= height || x + dx < 0 || x + dx >= width) continue;
            const std::size_t j = static_cast<std::size_t>((y + dy) * width + x + dx);
            if (fired[j] || rng.uniform() >= probability) continue;
            if (when[j] > when[next]) when[j] = when[next];
          }
        }
      }
    }
    return h;
  }
};

}  // namespace tofsim::sensors::test
