#include "tofsim/lidar/ZoneDistance.h"

#include <algorithm>
#include <cmath>

namespace tofsim::lidar {

double peakTime_s(const float* histogram, const TimeAxis& axis) {
  int32_t peak = -1;
  for (int32_t b = 0; b < axis.bins; ++b) {
    if (histogram[b] > 0.0f && (peak < 0 || histogram[b] > histogram[peak])) peak = b;
  }
  if (peak < 0) return -1.0;
  const double before = peak > 0 ? histogram[peak - 1] : 0.0;
  const double at = histogram[peak];
  const double after = peak + 1 < axis.bins ? histogram[peak + 1] : 0.0;
  double offset = 0.0;
  if (before > 0.0 && after > 0.0) {
    const double lb = std::log(before), la = std::log(at), lc = std::log(after);
    const double curvature = lb - 2.0 * la + lc;  // < 0 at a strict peak
    if (curvature < 0.0) offset = std::clamp(0.5 * (lb - lc) / curvature, -0.5, 0.5);
  } else {
    // A neighbour is empty (an echo of one or two bins, as direct light
    // without a pulse shape gives): the three bins' energy-weighted centre.
    offset = (after - before) / (before + at + after);
  }
  return axis.binCenter_s(peak) + offset * axis.bin_width_s;
}

double zoneDistance_m(const float* histogram, const TimeAxis& axis) {
  const double t = peakTime_s(histogram, axis);
  return t < 0.0 ? 0.0 : axis.depthOf_m(t);
}

}  // namespace tofsim::lidar
