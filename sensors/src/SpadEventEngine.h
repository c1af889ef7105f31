#pragma once
// Private to the SPAD model: the exact event-driven SPAD of one pixel, the
// reference path (issue 24's engine) that the fast binomial draws
// (SpadSampling.h, freeRunningProbabilities) are tested against, and the
// model's path wherever an effect correlates bins or cycles (multi-stop TDCs,
// dead time past the cycle's end, afterpulses). It steps one SpadDetector
// (SpadDetector.h) from avalanche to avalanche, so its cost grows with the
// detections, not the cycles; the array driver (SpadArrayEvents.h) steps
// many the same way, for exact crosstalk.

#include <cstdint>
#include <vector>

#include "SpadDetector.h"
#include "tofsim/sensors/Random.h"

namespace tofsim::sensors::detail {

/// `flux[i]`: expected primaries per cycle in TDC bin i (PDE applied, the
/// laser period = the TDC range). Adds to `h` (flux.size() bins) the recorded
/// avalanches of `cycles` cycles of a detector with `laws`. Synchronous
/// first photon: stops 1, deadBins 0; free-running: stops 0.
void spadEvents(const std::vector<double>& flux, uint64_t cycles, const DetectorLaws& laws,
                Rng& rng, std::vector<double>& h);

}  // namespace tofsim::sensors::detail
