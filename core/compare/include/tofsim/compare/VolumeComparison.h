#pragma once
// Error metrics between a transient volume A (the render under test) and B
// (the reference), for validation tests, `tofsim compare` and benchmarks.
//
// Definitions (sums over every pixel y, x, channel c and, where named, bin t):
//  - steady S(y,x,c) = sum_t v(y,x,t,c), accumulated in double;
//  - steadyRelativeL1   = sum |S_A - S_B| / sum |S_B|;
//  - steadyRmse         = sqrt(mean over (y,x,c) of (S_A - S_B)^2), in the volume's
//                         radiance unit (W / (m^2 sr));
//  - transientRelativeL1 = sum over (y,x,t,c) |A - B| / sum |B|;
//    a relative L1 with sum |B| = 0 is 0 when A = B and +inf otherwise;
//  - earliest arrival of a pixel: with e(t) = sum_c v(y,x,t,c), the leading edge
//    (TimeAxis::binStart_s) of the first bin with e(t) >= threshold * max_t e(t).
//    Pixels whose peak is <= 0 have no arrival. Differences are A - B, seconds,
//    over the pixels where both have an arrival;
//  - energy curve: E(t) = sum over (y,x,c) v(y,x,t,c), per bin.
// A and B must have the same width, height, channels and time axis (start and
// bin width equal to 1e-9 relative), else InputError.

#include <cstddef>
#include <string>
#include <vector>

#include "tofsim/volume/TransientVolume.h"

namespace tofsim::compare {

struct CompareOptions {
  /// Fraction of a pixel's peak (summed over channels) that counts as arrival.
  double arrival_threshold = 0.05;
};

struct VolumeComparison {
  TimeAxis axis;  ///< shared by A and B
  double steadyRelativeL1 = 0.0;
  double steadyRmse = 0.0;  ///< W / (m^2 sr)
  double transientRelativeL1 = 0.0;
  /// Mean and max of |arrival_A - arrival_B| over pixels where both arrive, s.
  double meanEarliestArrivalDifference_s = 0.0;
  double maxEarliestArrivalDifference_s = 0.0;
  std::size_t arrivalPixelsCompared = 0;   ///< pixels with an arrival in both
  std::size_t arrivalPixelsUnmatched = 0;  ///< pixels with an arrival in one only
  /// Per pixel arrival_A - arrival_B (H, W, 1), seconds; 0 where not compared.
  Image earliestArrivalDifference_s;
  std::vector<double> energyA;  ///< E(t) of A, one per bin
  std::vector<double> energyB;  ///< E(t) of B, one per bin
};

/// Compares A (under test) against B (reference). Throws InputError on a
/// shape or time axis mismatch.
VolumeComparison compareVolumes(const TransientVolume& a, const TransientVolume& b,
                                const CompareOptions& options = {});

/// First bin with e(t) >= threshold * peak for pixel (y, x), or -1 when the
/// pixel's peak is <= 0.
int32_t earliestArrivalBin(const TransientVolume& v, int32_t y, int32_t x, double threshold);

/// "bin,time_s,energy_a,energy_b" header and one line per bin; time_s is the
/// bin's centre. Values printed with 17 significant digits (round-trip).
std::string energyCurveCsv(const VolumeComparison& comparison);

/// A short human-readable table of the scalar metrics, one per line.
std::string summaryTable(const VolumeComparison& comparison);

}  // namespace tofsim::compare
