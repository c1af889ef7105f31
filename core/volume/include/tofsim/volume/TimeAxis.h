#pragma once
// The time axis of a transient volume. Bin i covers the half-open interval
// [start_s + i * bin_width_s, start_s + (i + 1) * bin_width_s) of arrival time at
// the sensor, measured from the emission of the light's impulse at t = 0.

#include <cstdint>

namespace tofsim {

struct TimeAxis {
  double start_s = 0.0;       ///< time of the leading edge of bin 0, seconds
  double bin_width_s = 0.0;   ///< seconds per bin, > 0
  int32_t bins = 0;           ///< number of bins, > 0

  double end_s() const { return start_s + bin_width_s * bins; }
  /// Leading edge of bin i, seconds.
  double binStart_s(int32_t i) const { return start_s + bin_width_s * i; }
  double binCenter_s(int32_t i) const { return start_s + bin_width_s * (i + 0.5); }
  /// Bin holding time t, or -1 when t lies outside [start_s, end_s).
  int32_t binOf(double t_s) const;
  /// The same quantities as optical path length in metres (c * t).
  double start_m() const;
  double bin_width_m() const;
};

}  // namespace tofsim
