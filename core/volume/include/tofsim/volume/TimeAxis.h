#pragma once
// The time axis of a transient volume. Bin i covers the half-open interval
// [start_s + i * bin_width_s, start_s + (i + 1) * bin_width_s) of arrival time at
// the sensor, measured from the emission of the light's impulse at t = 0.
// The axis also says what a time means as a distance: light travels at
// c / index_of_refraction, and with camera_unwarp the surface -> camera leg is
// not part of the time (so a co-located camera and light see one leg, not two).

#include <cstdint>

namespace tofsim {

/// What TimeAxis::binOf returns off the axis: both are negative, so a caller
/// that only needs "on the axis or not" tests bin < 0.
constexpr int32_t kBeforeAxis = -1;
constexpr int32_t kAfterAxis = -2;

struct TimeAxis {
  double start_s = 0.0;      ///< time of the leading edge of bin 0, seconds
  double bin_width_s = 0.0;  ///< seconds per bin, > 0
  int32_t bins = 0;          ///< number of bins, > 0
  /// Of the medium filling the scene, >= 1: light covers c / eta metres per second.
  double index_of_refraction = 1.0;
  /// true: the arrival time leaves out the surface -> camera leg (time at the surface).
  bool camera_unwarp = false;

  double end_s() const { return start_s + bin_width_s * bins; }
  /// Leading edge of bin i, seconds.
  double binStart_s(int32_t i) const { return start_s + bin_width_s * i; }
  double binCenter_s(int32_t i) const { return start_s + bin_width_s * (i + 0.5); }
  /// Bin holding time t; kBeforeAxis when t < start_s (or NaN),
  /// kAfterAxis when t >= end_s.
  int32_t binOf(double t_s) const;
  /// The same quantities as optical path length in metres (c * t, vacuum c:
  /// the renderers compare these with eta x geometric length).
  double start_m() const;
  double bin_width_m() const;
  /// Speed of light in the scene's medium, c / index_of_refraction, m/s.
  double speedOfLight_m_per_s() const;
  /// Metres of depth per second of arrival time for a camera with the light at
  /// it: (c / eta) / 2 for the round trip, (c / eta) with camera_unwarp (the
  /// time then holds the light -> surface leg only).
  double depthPerSecond_m_per_s() const;
  /// Depth (distance from a co-located camera and light) of light arriving at t_s.
  double depthOf_m(double t_s) const { return depthPerSecond_m_per_s() * t_s; }
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
