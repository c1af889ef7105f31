#pragma once
// Private helpers of the SPAD model: depth from a histogram's peak, and the
// plot of a few pixels' histograms.

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::sensors {

/// axis.depthOf_m(t) ((c / eta) t / 2) for the time t of the histogram's maximum, refined by a
/// parabola through the maximum and its neighbours. NaN for an empty histogram.
double peakDepth_m(const std::vector<double>& histogram, const TimeAxis& axis);

/// Coates' flux of one bin of h counts when `remaining` cycles had no earlier
/// detection (coatesEstimate's terms; a bin that took every remaining cycle
/// gets ln(remaining + 1)).
inline double coatesBinFlux(double h, double remaining) {
  if (remaining <= 0.0 || h == 0.0) return 0.0;
  return h >= remaining ? std::log(remaining + 1.0) : -std::log1p(-h / remaining);
}

/// peakDepth_m(coatesEstimate(counts, cycles), axis), the same double, with
/// logarithms only for bins that may hold the maximum (the flux grows with
/// h / remaining) and the parabola's neighbours.
double coatesPeakDepth_m(const std::vector<double>& counts, int64_t cycles, const TimeAxis& axis);

/// The pixels to plot: `pixels` ((x, y) each), or the centre when empty.
/// Throws InputError for a pixel outside the W x H image.
std::vector<std::array<int32_t, 2>> plotPixels(const std::vector<std::array<int32_t, 2>>& pixels,
                                               int32_t H, int32_t W);

/// HistogramPlot "spad_histograms": one series per pixel of `pixels` (from
/// plotPixels), `histograms` holding their counts in the same order.
SensorOutput histogramPlot(const std::vector<std::array<int32_t, 2>>& pixels,
                           const std::vector<std::vector<float>>& histograms, const TimeAxis& axis);

}  // namespace tofsim::sensors
