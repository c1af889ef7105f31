#pragma once
// Private to the SPAD model: afterpulsing on the fast path, first order in
// the afterpulse mean (issue 24, research note 1.1). The releases become extra
// flux, flux'_i = flux_i + mean sum_j m_j a_(i - j), m_j the expected
// avalanches per cycle in bin j (recorded or not: the free-running steady
// state of flux' with the dead time) and a the release kernel from an
// avalanche's bin (live again deadBins + 1 bins later, then the delay
// mixture, or a measured table's mass per whole bin), folded on the cycle;
// iterated to its fixed point. The fast draws
// then run on flux' (on its m_j, which the fixed point gives with it). What it leaves out (releases
// as a Poisson flux, not a renewal; reset traps) is its error against the engine
// (SpadFastAfterpulseTest).

#include <cstdint>
#include <vector>

#include "SpadDetector.h"

namespace tofsim::sensors::detail {

/// flux' and the free-running detections per cycle it gives.
struct FirstOrderAfterpulses {
  std::vector<double> flux;        ///< flux' per bin and cycle
  std::vector<double> detections;  ///< m_i: the steady state of flux' (freeRunningProbabilities)
};

/// flux' of `flux` (per bin and cycle) for a detector with `deadBins` dead
/// bins and afterpulses `law` (its weights need not be normalised), and its
/// steady state: one fixed point for both, iterated a laser cycle at a time
/// (each cycle on the flux' of the cycle before's detections), to the flux'
/// tolerance (1e-12) and freeRunningProbabilities' steady state tolerance.
/// `out` is reused (its vectors keep their capacity); returned.
const FirstOrderAfterpulses& firstOrderAfterpulses(const std::vector<double>& flux,
                                                   int32_t deadBins, const AfterpulseLaw& law,
                                                   FirstOrderAfterpulses& out);

}  // namespace tofsim::sensors::detail
