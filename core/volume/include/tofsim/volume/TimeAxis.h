#pragma once
// The time axis of a transient volume. Bin i covers the half-open interval
// [start_s + i * bin_width_s, start_s + (i + 1) * bin_width_s) of arrival time at
// the sensor, measured from the emission of the light's impulse at t = 0.

#include <cstdint>

namespace tofsim {

/// What TimeAxis::binOf returns off the axis: both are negative, so a caller
/// that only needs "on the axis or not" tests bin < 0.
constexpr int32_t kBeforeAxis = -1;
constexpr int32_t kAfterAxis = -2;

struct TimeAxis {
  double start_s = 0.0;       ///< time of the leading edge of bin 0, seconds
  double bin_width_s = 0.0;   ///< seconds per bin, > 0
  int32_t bins = 0;           ///< number of bins, > 0

  double end_s() const { return start_s + bin_width_s * bins; }
  /// Leading edge of bin i, seconds.
  double binStart_s(int32_t i) const { return start_s + bin_width_s * i; }
  double binCenter_s(int32_t i) const { return start_s + bin_width_s * (i + 0.5); }
  /// Bin holding time t; kBeforeAxis when t < start_s (or NaN),
  /// kAfterAxis when t >= end_s.
  int32_t binOf(double t_s) const;
  /// The same quantities as optical path length in metres (c * t).
  double start_m() const;
  double bin_width_m() const;
};

/// Energy (radiance summed over channels) that fell off a time axis, by side:
/// light before the first bin and light after the last need different fixes
/// (time.start vs time.bins), so a run reports them apart.
struct AxisLoss {
  double before = 0.0;
  double after = 0.0;

  /// Adds `value` to the side named by a negative bin from TimeAxis::binOf.
  void add(int32_t offAxisBin, double value) {
    (offAxisBin == kAfterAxis ? after : before) += value;
  }
  double total() const { return before + after; }
  AxisLoss& operator+=(const AxisLoss& other) {
    before += other.before;
    after += other.after;
    return *this;
  }
};

}  // namespace tofsim
