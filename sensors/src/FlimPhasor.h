#pragma once
// Private to the SPAD model: the FLIM user's phasor. The first harmonic of
// a pixel's histogram at the laser's repetition frequency (the TDC's range
// is the laser period: f = 1 / (bins x bin_width)), each bin at its centre,
// normalised by the counts above the background (a constant background has
// no first harmonic: it would only pull the phasor to the origin), divided
// by the instrument kernel's phasor (IRF calibration) and turned back by the
// decay's onset (the light's arrival time, which varies with the pixel's
// path): a mono-exponential of lifetime tau lands on the universal
// semicircle g = 1 / (1 + (w tau)^2), s = w tau / (1 + (w tau)^2), w = 2 pi f;
// a mixture inside it, on the chord between its lifetimes' points at their
// photon fractions. Model: sensors/README.md, "FLIM: lifetime and phasor".

#include <complex>
#include <cstdint>
#include <limits>
#include <vector>

#include "tofsim/sensors/TimeKernel.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::sensors::detail {

struct Phasor {
  double g = std::numeric_limits<double>::quiet_NaN();
  double s = std::numeric_limits<double>::quiet_NaN();
};

/// The semicircle's point of lifetime tau at frequency f.
Phasor monoExponentialPhasor(double lifetime_s, double frequency_Hz);

class FlimPhasor {
 public:
  FlimPhasor(const BinKernel& kernel, const TimeAxis& axis);

  double frequency_Hz() const { return frequency_Hz_; }

  /// The calibrated phasor of `h` (axis.bins counts), `background` counts
  /// per bin, the decay starting at onset_s on the axis; NaN when no counts
  /// are above the background.
  Phasor of(const std::vector<double>& h, double background, double onset_s) const;

 private:
  TimeAxis axis_;
  double frequency_Hz_;
  std::vector<double> cos_, sin_;  ///< of w t_n, t_n bin n's centre from the axis start
  std::complex<double> kernel_;    ///< the kernel's phasor
};

/// The phasor plot's raster: pixels per (g, s) cell, g in [0, 1] left to
/// right, s in [0, 0.6] bottom to top, cells kPhasorCell wide, each drawn
/// kPhasorMark cells wide (the largest count where marks overlap); the
/// semicircle's empty cells set to kPhasorCircleLevel of the largest count
/// (at least 1): the curve shows without hiding the pixels that lie on it.
inline constexpr int32_t kPhasorPlotWidth = 400, kPhasorPlotHeight = 240;
inline constexpr double kPhasorCell = 1.0 / kPhasorPlotWidth;
/// Each cell's count is drawn as a square this many cells wide.
inline constexpr int32_t kPhasorMark = 5;
/// The semicircle's value in the plot, as a share of the top count.
inline constexpr float kPhasorCircleLevel = 0.3f;
std::vector<float> phasorPlot(const std::vector<float>& g, const std::vector<float>& s);

}  // namespace tofsim::sensors::detail
