#include "SpadGate.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

namespace {
// int_-inf^t of a unit step at c smoothed into a linear ramp of width r
// centred on c: 0 before the ramp, t - c after it, quadratic on it.
double rampIntegral(double t, double c, double r) {
  if (r <= 0.0) return std::max(0.0, t - c);
  const double a = c - 0.5 * r;
  if (t <= a) return 0.0;
  if (t >= a + r) return t - c;
  return (t - a) * (t - a) / (2.0 * r);
}

double rampAt(double t, double c, double r) {
  if (r <= 0.0) return t >= c ? 1.0 : 0.0;
  return std::clamp((t - (c - 0.5 * r)) / r, 0.0, 1.0);
}
}  // namespace

int32_t TdcBins::binAt(double t) const {
  int32_t i = 0;
  if (edges.empty()) {
    i = static_cast<int32_t>(
        std::clamp(std::floor((t - axis.start_s) / axis.bin_width_s), 0.0, axis.bins - 1.0));
  } else {
    i = static_cast<int32_t>(std::upper_bound(edges.begin(), edges.end(), t) - edges.begin()) - 1;
  }
  return std::clamp(i, 0, axis.bins - 1);
}

TdcBins tdcBins(const SpadParams& p, const TimeAxis& axis) {
  TdcBins bins{axis, {}};
  const std::vector<double>& dnl = p.tdc_dnl.values;
  if (std::none_of(dnl.begin(), dnl.end(), [](double d) { return d != 0.0; })) return bins;
  if (static_cast<int32_t>(dnl.size()) != axis.bins) {
    throw InputError("SPAD tdc_dnl has " + std::to_string(dnl.size()) + " values but the TDC has " +
                     std::to_string(axis.bins) + " bins");
  }
  bins.edges.resize(dnl.size() + 1);
  bins.edges[0] = axis.start_s;
  double inl = 0.0;  // sum_{i<k} (1 + DNL_i), in LSB
  for (std::size_t k = 0; k < dnl.size(); ++k) {
    TOFSIM_CHECK(dnl[k] > -1.0);
    inl += 1.0 + dnl[k];
    bins.edges[k + 1] = axis.start_s + inl * axis.bin_width_s;
  }
  return bins;
}

double SpadGate::at(double t) const {
  return rampAt(t, start_s, rise_s) - rampAt(t, end_s, fall_s);
}

double SpadGate::binAverage(double b0, double width) const {
  if (rise_s == 0.0 && fall_s == 0.0) {  // hard edges: the covered fraction
    return std::max(0.0, std::min(b0 + width, end_s) - std::max(b0, start_s)) / width;
  }
  const auto G = [this](double t) {
    return rampIntegral(t, start_s, rise_s) - rampIntegral(t, end_s, fall_s);
  };
  return std::max(0.0, G(b0 + width) - G(b0)) / width;
}

SpadGate spadGate(const SpadParams& p) {
  SpadGate g{p.gate_start_s, p.gate_start_s + p.gate_width_s, p.gate_rise_s, p.gate_fall_s};
  TOFSIM_CHECK(g.rise_s >= 0.0 && g.fall_s >= 0.0);
  TOFSIM_CHECK(p.gate_width_s >= 0.5 * (g.rise_s + g.fall_s));  // the ramps do not overlap
  return g;
}

void applyGate(const SpadGate& gate, const TdcBins& bins, std::vector<double>& flux) {
  for (int32_t i = 0; i < bins.count(); ++i)
    flux[i] *= gate.binAverage(bins.start(i), bins.width(i));
}

double gatedFlux(const SpadGate& gate, const TdcBins& bins, const std::vector<double>& flux) {
  const int32_t i0 = bins.binAt(gate.firstArmed_s()), i1 = bins.binAt(gate.lastArmed_s());
  double sum = 0.0;
  for (int32_t i = i0; i <= i1; ++i) sum += gate.binAverage(bins.start(i), bins.width(i)) * flux[i];
  return sum;
}

}  // namespace tofsim::sensors::detail
