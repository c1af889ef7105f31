#pragma once
// A multizone sensor's own per-zone distance (the VL53L5CX's distance_mm,
// the TMF8828's per-zone targets): the device computes it on chip from the
// zone's histogram. ST and ams publish no algorithm; tofsim's is the usual
// one for pulsed histograms: the highest bin b, refined by the vertex of
// the parabola through the logarithms of bins b - 1, b, b + 1 (exact for a
// Gaussian echo sampled at the bin centres), the offset clamped to half a
// bin; where a neighbour is empty (direct light without a pulse shape fills
// one or two bins) the energy-weighted centre of the three bins instead (an
// echo in one bin: its centre).
// The distance is the radial range (c / eta) t / 2 of that time (t / 1
// with time.camera_unwarp), as TimeAxis::depthOf_m.

#include <cstdint>

#include "tofsim/volume/TimeAxis.h"

namespace tofsim::lidar {

/// The peak time (s) of a histogram of axis.bins floats with the sub-bin
/// fit; a negative value when every bin is 0.
double peakTime_s(const float* histogram, const TimeAxis& axis);

/// peakTime_s as a range (m); 0 when every bin is 0.
double zoneDistance_m(const float* histogram, const TimeAxis& axis);

}  // namespace tofsim::lidar
