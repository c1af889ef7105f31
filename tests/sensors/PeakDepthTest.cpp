// The SPAD's Coates depth without a logarithm per bin (sensors/src/PeakDepth)
// gives the very double of the peak of coatesEstimate.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "PeakDepth.h"
#include "tofsim/sensors/Random.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {
namespace {

void expectSameDouble(const std::vector<double>& h, int64_t cycles, const TimeAxis& axis) {
  const double expected = peakDepth_m(coatesEstimate(h, cycles), axis);
  const double got = coatesPeakDepth_m(h, cycles, axis);
  if (std::isnan(expected)) {
    EXPECT_TRUE(std::isnan(got));
  } else {
    EXPECT_EQ(got, expected);
  }
}

TEST(PeakDepthTest, CoatesPeakDepthIsThePeakOfCoatesEstimate) {
  TimeAxis axis;
  axis.start_s = 1e-9;
  axis.bin_width_s = 10e-12;
  axis.bins = 50;
  Rng rng(3, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    const int64_t cycles = 1 + static_cast<int64_t>(rng.uniform() * 3000.0);
    std::vector<double> h(50, 0.0);
    uint64_t remaining = static_cast<uint64_t>(cycles);
    const double q = 0.2 * rng.uniform();
    for (double& c : h) {  // pile-up histograms, some saturated before the end
      c = static_cast<double>(rng.binomial(remaining, q));
      remaining -= static_cast<uint64_t>(c);
    }
    expectSameDouble(h, cycles, axis);
  }
  expectSameDouble(std::vector<double>(50, 0.0), 100, axis);  // empty: NaN
  std::vector<double> ties(50, 0.0);
  ties[3] = ties[7] = 5.0;  // the later bin has fewer remaining cycles: its flux is larger
  expectSameDouble(ties, 1000, axis);
  std::vector<double> saturated(50, 0.0);
  saturated[10] = 999.0;
  saturated[11] = 1.0;  // every remaining cycle: ln(2)
  expectSameDouble(saturated, 1000, axis);
  saturated[0] = 1.0;
  expectSameDouble(saturated, 1001, axis);
}

}  // namespace
}  // namespace tofsim::sensors
