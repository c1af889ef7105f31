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
  double offset = 0.0;
  if (peak > 0 && peak + 1 < axis.bins && histogram[peak - 1] > 0.0f &&
      histogram[peak + 1] > 0.0f) {
    const double before = std::log(double(histogram[peak - 1]));
    const double at = std::log(double(histogram[peak]));
    const double after = std::log(double(histogram[peak + 1]));
    const double curvature = before - 2.0 * at + after;  // < 0 at a strict peak
    if (curvature < 0.0) offset = std::clamp(0.5 * (before - after) / curvature, -0.5, 0.5);
  }
  return axis.binCenter_s(peak) + offset * axis.bin_width_s;
}

double zoneDistance_m(const float* histogram, const TimeAxis& axis) {
  const double t = peakTime_s(histogram, axis);
  return t < 0.0 ? 0.0 : axis.depthOf_m(t);
}

}  // namespace tofsim::lidar
