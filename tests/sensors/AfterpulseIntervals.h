#pragma once
// The afterpulse tests' renewal law (SpadAfterpulseTest, SpadAfterpulseTableTest):
// a free-running detector with a dark rate r per bin and traps reset at each
// avalanche, its live times Y (from the end of each dead time to the next
// avalanche, in bins), their survival e^-ry E[S(y)^N] with N releases pending
// and S the delay's survival (e^-ry (1 - p + p S) for Bernoulli(p),
// e^-ry e^-mu (1 - S) for Poisson(mu)), and Pearson's statistic of one against
// the other.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "SpadDetector.h"
#include "support/ChiSquare.h"
#include "tofsim/sensors/Random.h"

namespace tofsim::sensors {

inline std::vector<double> liveTimes(double r, const detail::DetectorLaws& laws, uint64_t cycles,
                                     uint64_t seed) {
  const std::vector<double> flux(50, r);
  detail::SpadDetector detector(flux, laws, cycles);
  Rng rng(seed, 2);
  std::vector<double> h(flux.size(), 0.0), y;
  const auto absolute = [](const detail::Moment& m) {
    return static_cast<double>(m.cycle) * 50.0 + m.position;
  };
  for (;;) {
    const double live = absolute(detector.liveFrom());
    const detail::Event e = detector.next(rng);
    if (!(e.at.cycle < cycles)) break;
    y.push_back(absolute(e.at) - live);
    detector.fire(e, rng, h);
  }
  return y;
}

struct IntervalLaw {
  double r;
  bool poisson;
  double mean;
  std::function<double(double)> delaySurvival;  ///< S(y), y in bins
  double survival(double y) const {
    const double s = delaySurvival(y);
    return std::exp(-r * y) * (poisson ? std::exp(-mean * (1.0 - s)) : 1.0 - mean + mean * s);
  }
};

/// S(y) = sum_k w_k e^(-y / tau_k) of a mixture of exponentials (w normalised).
inline std::function<double(double)> mixtureSurvival(std::vector<double> taus,
                                                     std::vector<double> weights) {
  return [taus, weights](double y) {
    double s = 0.0;
    for (std::size_t k = 0; k < taus.size(); ++k) s += weights[k] * std::exp(-y / taus[k]);
    return s;
  };
}

/// Pearson's statistic of the live times in cells [0, 0.25), [0.25, 0.5), ...
/// up to 80 bins, and the rest.
inline test::ChiSquare intervalChiSquare(const std::vector<double>& y, const IntervalLaw& law) {
  const double width = 0.25, last = 80.0;
  const auto cells = static_cast<std::size_t>(last / width) + 1;
  std::vector<double> observed(cells, 0.0), expected(cells, 0.0);
  for (double v : y) observed[std::min(cells - 1, static_cast<std::size_t>(v / width))] += 1.0;
  for (std::size_t c = 0; c + 1 < cells; ++c) {
    expected[c] = y.size() * (law.survival(c * width) - law.survival((c + 1) * width));
  }
  expected.back() = y.size() * law.survival(last);
  return test::pearson(observed, expected);
}

}  // namespace tofsim::sensors
