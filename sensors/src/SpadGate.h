#pragma once
// Private to the SPAD model: the TDC's bins (uniform, or the true unequal
// bins of a TDC with differential non-linearity) and the gate's sensitivity
// g(t) in [0, 1] of each cycle, averaged exactly over each bin.

#include <cstdint>
#include <vector>

#include "tofsim/sensors/Spad.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::sensors::detail {

/// The TDC's bins: bin i covers [start(i), start(i) + width(i)). Without
/// edges, the uniform bins of `axis` (the same doubles the model has always
/// used); with edges (axis.bins + 1 of them), those.
struct TdcBins {
  TimeAxis axis;
  std::vector<double> edges;  ///< empty: uniform

  int32_t count() const { return axis.bins; }
  double start(int32_t i) const {
    return edges.empty() ? axis.start_s + i * axis.bin_width_s : edges[i];
  }
  double width(int32_t i) const {
    return edges.empty() ? axis.bin_width_s : edges[i + 1] - edges[i];
  }
  /// The bin holding time t, clamped to [0, count() - 1].
  int32_t binAt(double t) const;
};

/// The bins of the TDC whose nominal axis is `axis`: with p.tdc_dnl, the
/// edges e_k = offset + sum_{i<k} LSB (1 + DNL_i).
TdcBins tdcBins(const SpadParams& p, const TimeAxis& axis);

/// g(t): 0 before the rising edge, 1 between the edges, 0 after; each edge a
/// linear ramp of its transition time centred on its 50 % time (start_s,
/// end_s), or a step for 0. The ramps do not overlap (checked).
struct SpadGate {
  double start_s = 0.0;  ///< 50 % point of the rising edge
  double end_s = 0.0;    ///< 50 % point of the falling edge
  double rise_s = 0.0;   ///< 0 -> 1 time of the rising ramp
  double fall_s = 0.0;   ///< 1 -> 0 time of the falling ramp

  SpadGate shifted(double by_s) const { return {start_s + by_s, end_s + by_s, rise_s, fall_s}; }
  double firstArmed_s() const { return start_s - 0.5 * rise_s; }
  double lastArmed_s() const { return end_s + 0.5 * fall_s; }
  /// g(t) itself (the tests' oracle integrates it).
  double at(double t) const;
  /// (1 / width) int_{b0}^{b0 + width} g(t) dt, exact (the integral of a
  /// linear ramp is piecewise quadratic).
  double binAverage(double b0, double width) const;
};

/// The gate of p (gate_start, gate_width, gate_rise, gate_fall).
SpadGate spadGate(const SpadParams& p);

/// flux_i *= the gate's average over bin i.
void applyGate(const SpadGate& gate, const TdcBins& bins, std::vector<double>& flux);

/// sum_i (gate's average over bin i) flux_i: the expected detections per
/// cycle inside the gate, without losses.
double gatedFlux(const SpadGate& gate, const TdcBins& bins, const std::vector<double>& flux);

}  // namespace tofsim::sensors::detail
