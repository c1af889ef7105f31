#pragma once
// Private to the SPAD model: the exact event-driven SPAD of one pixel, the
// reference path (issue 24's engine) that the fast binomial draws
// (SpadSampling.h, freeRunningProbabilities) are tested against. It follows
// the detector through time instead of drawing bin counts: the next event
// after the detector is live again is where the cumulative flux from there
// crosses an Exp(1) draw, and whole empty cycles are skipped at once (a
// geometric number of them in synchronous mode, a multiple of the cycle's
// flux in free-running mode), so its cost grows with the detections, not the
// cycles. The effects still to come (afterpulses, crosstalk, multi-stop
// TDCs) are events in this same loop.

#include <cstdint>
#include <vector>

#include "tofsim/sensors/Random.h"

namespace tofsim::sensors::detail {

/// Afterpulses, free-running mode: each avalanche leaves with `probability`
/// one trapped carrier whose release, an Exp(delay_bins) time after the end
/// of the hold-off, is a detection unless a photon comes first; the next
/// avalanche clears the traps of the last (Bernoulli afterpulsing with one
/// exponential delay, the renewal model of the closed form in the tests).
struct Afterpulsing {
  double probability = 0.0;
  double delay_bins = 1.0;
};

/// `flux[i]`: expected detections per cycle in TDC bin i (PDE applied, the
/// laser period = the TDC range). Adds to `h` (flux.size() bins) the
/// detections of `cycles` cycles:
///  - deadBins < 0: synchronous, the first detection of each cycle, the
///    detector live again at every pulse;
///  - deadBins >= 0: free-running, every detection, each followed by
///    deadBins dead bins that may run into the next cycles (non-paralysable).
void spadEvents(const std::vector<double>& flux, uint64_t cycles, int32_t deadBins, Rng& rng,
                std::vector<double>& h, const Afterpulsing& afterpulsing = {});

}  // namespace tofsim::sensors::detail
