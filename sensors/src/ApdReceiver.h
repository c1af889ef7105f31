#pragma once
// One pixel of the linear-mode APD (Apd.h): its noisy digitised current
// from its expected photo-electrons, and the echoes its threshold finds.

#include <cstdint>
#include <vector>

#include "tofsim/sensors/Apd.h"
#include "tofsim/sensors/Random.h"

namespace tofsim::sensors::detail {

/// Scratch a pixel reuses (one per thread's block).
struct ApdScratch {
  std::vector<double> pulsed, current, threshold;
};

/// `signal_e` (rx.axis.bins expected primary photo-electrons per sample,
/// before the pulse's shape) -> `out_A`, the sampled current at the TIA's
/// input, A: Poisson primaries of signal + background + bulk dark current,
/// each multiplied by a gain of mean M and variance M^2 (F - 1) (their sum a
/// gamma law of the same moments: mean M N, variance M^2 (F - 1) N), the
/// surface dark current's Poisson electrons, white TIA noise, then the
/// bandwidth's filter and the ADC.
void apdSamples(const ApdParams& p, const ApdReceiver& rx, const std::vector<double>& signal_e,
                Rng& rng, ApdScratch& scratch, std::vector<double>& out_A);

struct ApdEcho {
  double range_m = 0.0;
  double amplitude_A = 0.0;
};

/// The echoes of `samples_A`: each run of samples above their thresholds
/// (`thresholds_A`, apdThresholds) is one: its time the current-weighted mean of the run's sample times (as
/// core/lidar's Echoes: unbiased for a symmetric pulse, and it averages the
/// noise of every sample), its range that time's depth (TimeAxis::depthOf_m),
/// its amplitude the run's highest sample; the first `maxReturns` in time
/// order.
std::vector<ApdEcho> apdEchoes(const std::vector<double>& samples_A,
                               const std::vector<double>& thresholds_A, const ApdReceiver& rx,
                               int32_t maxReturns);

}  // namespace tofsim::sensors::detail
