#pragma once
// A SPAD simulated bin by bin, cycle by cycle: slow and obviously right, the
// oracle the event engine (SpadDetector.h) is compared with where no closed
// form exists. Written apart from the engine: a live bin fires with
// probability q_i = 1 - e^-flux_i or when a pending release falls in it;
// then dead for `dead` more bins; releases at the live moment plus an
// exponential delay; releases that come while dead are lost.

#include <cmath>
#include <cstdint>
#include <vector>

#include "tofsim/sensors/Random.h"

namespace tofsim::sensors::test {

struct BruteForceSpad {
  std::vector<double> flux;  ///< per bin and cycle
  int32_t dead = 0;          ///< dead bins after the firing one
  int64_t stops = 1;         ///< recorded per cycle; 0: all
  bool poisson = false;      ///< afterpulse count Poisson(mean), else Bernoulli(mean)
  double mean = 0.0;
  std::vector<double> taus = {1.0};  ///< mixture means, bins
  std::vector<double> weights = {1.0};
  bool reset = true;  ///< an avalanche drops the pending releases

  std::vector<double> run(uint64_t cycles, Rng& rng) const {
    const auto B = static_cast<int64_t>(flux.size());
    std::vector<double> h(flux.size(), 0.0);
    std::vector<double> pending;  // absolute times, bins
    double total = 0.0;
    for (double w : weights) total += w;
    int64_t liveBin = 0;
    for (uint64_t c = 0; c < cycles; ++c) {
      int64_t recorded = 0;
      for (int64_t i = 0; i < B; ++i) {
        const int64_t t = static_cast<int64_t>(c) * B + i;
        if (t < liveBin) continue;
        bool fires = rng.uniform() < -std::expm1(-flux[i]);
        for (double p : pending) fires = fires || p < t + 1.0;
        if (!fires) continue;
        if (stops == 0 || recorded < stops) {
          h[i] += 1.0;
          ++recorded;
        }
        liveBin = t + dead + 1;
        std::vector<double> kept;
        for (double p : pending) {
          if (!reset && p >= liveBin) kept.push_back(p);
        }
        pending = kept;
        const uint64_t n = poisson ? rng.poisson(mean) : (rng.uniform() < mean ? 1 : 0);
        for (uint64_t k = 0; k < n; ++k) {
          double u = rng.uniform() * total;
          std::size_t j = 0;
          while (j + 1 < taus.size() && u >= weights[j]) u -= weights[j++];
          pending.push_back(liveBin - taus[j] * std::log1p(-rng.uniform()));
        }
      }
    }
    return h;
  }
};

}  // namespace tofsim::sensors::test
