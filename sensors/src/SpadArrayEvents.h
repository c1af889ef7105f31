#pragma once
// Private to the SPAD model: crosstalk exact in the event engine (issue 24,
// item 7). The pixels of an array, each its own SpadDetector (SpadDetector.h)
// with its own random stream, stepped through one global time order: the
// earliest next event of any pixel fires first. An avalanche (primary,
// afterpulse or crosstalk; recorded or not) then tries each neighbour with
// the source pixel's stream: with probability p, after the crosstalk delay,
// and with the receiver's acceptance at the arrival's bin (its gate), it
// queues a Crosstalk event there, which the receiver fires if it is live
// then (dead time, its own stops): chains, back-triggering and the
// afterpulses of crosstalk avalanches follow.
// Determinism: crosstalk couples every pixel to every other over time (a
// chain can cross the array), so the array is one coupled region, stepped
// on one thread in the order (time, pixel); every draw comes from the pixel
// that makes it, so the bytes depend on the seed alone, not on the thread
// count or the spans the pixels came in. Memory O(pixels x bins): every
// pixel's flux is held until the last one is in.

#include <cstdint>
#include <vector>

#include "SpadDetector.h"
#include "tofsim/sensors/Random.h"

namespace tofsim::sensors::detail {

/// Crosstalk between the pixels of an array.
struct CrosstalkLaw {
  double probability = 0.0;  ///< per avalanche and neighbour
  bool eightNeighbours = false;
  double delayBins = 0.0;  ///< mean of the exponential delay, in TDC bins; 0: prompt
};

/// The pixels y * width + x of a width x height array. flux[px]: expected
/// primaries per cycle in each bin (as for spadEvents); accept[px]: per bin,
/// the probability that a crosstalk arrival there avalanches the pixel if it
/// is live (the gate's bin average; empty: 1); rngs[px]: the pixel's own
/// stream. Adds each pixel's recorded avalanches of `cycles` cycles to h[px].
/// With no crosstalk (p = 0) every pixel's bytes are spadEvents' on its
/// stream. `laws.everyAvalanche` is the caller's: on, a detector keeps
/// running after its cycle's last stop and those avalanches send crosstalk
/// too (the model, SpadStream); off, a single-stop detector whose dead time
/// ends in its cycle skips to the next pulse after its stop.
void spadArrayEvents(int32_t width, int32_t height, const std::vector<std::vector<double>>& flux,
                     const std::vector<std::vector<double>>& accept, uint64_t cycles,
                     const DetectorLaws& laws, const CrosstalkLaw& crosstalk,
                     std::vector<Rng>& rngs, std::vector<std::vector<double>>& h);

}  // namespace tofsim::sensors::detail
