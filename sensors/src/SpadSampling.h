#pragma once
// Private to the SPAD model: exact draws of a synchronous SPAD's histogram.

#include <cstdint>
#include <vector>

#include "FallingBinomial.h"
#include "tofsim/sensors/Random.h"

namespace tofsim::sensors::detail {

/// Reused buffers of firstPhotonHistogram (one per thread).
struct FirstPhotonScratch {
  std::vector<double> cdf;
  std::vector<int32_t> guide;
  FallingBinomial falling;  ///< its powers of (1 - q) are reused across pixels
};

/// The histogram over `cycles` laser cycles of the bin of each cycle's first
/// detection, flux_i expected detections per cycle in bin i: a draw of
/// Multinomial(cycles; p_0 .. p_{K-1}, none), p_i = q_i prod_{j<i} (1 - q_j),
/// q_i = 1 - exp(-flux_i). Exact, by whichever of two equivalent draws is
/// cheaper for this flux (chosen from the flux alone, so the same flux and
/// random stream give the same bytes):
///  - few detections: their number D ~ Binomial(cycles, 1 - exp(-sum flux)),
///    then each detection's bin by inverse CDF of p_i / (1 - exp(-sum flux))
///    (a guide table makes each draw O(1) on average); cost ~ D;
///  - many: K sequential conditional binomials (given no detection before
///    bin i, the first one is in bin i with probability q_i); cost ~ K: in
///    runs of bins of one flux (the ambient floor) O(1) each by a
///    FallingBinomial, elsewhere inversion below a mean of 10 and BTRS above.
/// `h` gets K counts.
void firstPhotonHistogram(const std::vector<double>& flux, uint64_t cycles, Rng& rng,
                          FirstPhotonScratch& scratch, std::vector<double>& h);

}  // namespace tofsim::sensors::detail
