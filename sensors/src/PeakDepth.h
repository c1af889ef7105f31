#pragma once
// Private helpers of the SPAD model: depth from a histogram's peak, and the
// plot of a few pixels' histograms.

#include <array>
#include <vector>

#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::sensors {

/// axis.depthOf_m(t) ((c / eta) t / 2) for the time t of the histogram's maximum, refined by a
/// parabola through the maximum and its neighbours. NaN for an empty histogram.
double peakDepth_m(const std::vector<double>& histogram, const TimeAxis& axis);

/// HistogramPlot "spad_histograms" of the given (x, y) pixels (centre if none)
/// taken from the (H, W, K) counts array.
SensorOutput histogramPlot(const SensorOutput& counts,
                           const std::vector<std::array<int32_t, 2>>& pixels, const TimeAxis& axis,
                           int32_t H, int32_t W);

}  // namespace tofsim::sensors
