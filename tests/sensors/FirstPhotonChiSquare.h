// Pearson's chi-square of a synchronous histogram against the first-photon
// law of a flux, with the cycles that saw no detection as one more cell (so
// the statistic also sees a wrong total). Shared by the engine's tests.
#pragma once

#include <vector>

#include "support/ChiSquare.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {

inline tofsim::test::ChiSquare againstFirstPhoton(std::vector<double> h,
                                                  const std::vector<double>& flux, double cycles) {
  std::vector<double> expected = firstPhotonProbabilities(flux);
  double none = 1.0, detected = 0.0;
  for (std::size_t t = 0; t < expected.size(); ++t) {
    none -= expected[t];
    detected += h[t];
    expected[t] *= cycles;
  }
  h.push_back(cycles - detected);
  expected.push_back(cycles * none);
  return tofsim::test::pearson(h, expected);
}

}  // namespace tofsim::sensors
