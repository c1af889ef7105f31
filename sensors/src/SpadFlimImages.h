#pragma once
// Private to the SPAD model: the FLIM outputs (SpadParams::flim), filled
// pixel by pixel from any thread: the lifetime of the mono-exponential fit
// (FlimFit.h) with its uncertainty, and the IRF-calibrated phasor
// (FlimPhasor.h) turned back by the fit's onset, of the histogram the other
// estimators read (pile-up corrected: N times Coates' flux in synchronous
// mode; the counts when free-running); then the phasor plot of all pixels.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "FlimFit.h"
#include "FlimPhasor.h"
#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors::detail {

/// The pixel's phasor as the outputs give it: its time zero the onset of a
/// second fit to the rising edge alone (bins up to the first fit's onset +
/// tau / 2 + the kernel's spread), where a mixture of lifetimes looks like
/// one exponential, so that a mixture's onset is not pulled by its tail;
/// its background the mean of the bins before the edge (at least 4 of them,
/// else the fit's), which a mono-exponential fit to a mixture would bias.
Phasor flimPhasorOf(const FlimFitter& fitter, const FlimPhasor& phasor, const std::vector<double>& h,
                    const FlimFit& fit, FlimFitter::Scratch& scratch);

class SpadFlimImages {
 public:
  SpadFlimImages(const SpadParams& p, const TimeAxis& axis, const BinKernel& kernel,
                 int32_t height, int32_t width);

  /// Pixel px from its pile-up corrected histogram `h` (each pixel once).
  void pixel(std::size_t px, const std::vector<double>& h, FlimFitter::Scratch& s) const;

  /// Appends spad_lifetime, spad_lifetime_sigma, spad_phasor_g and
  /// spad_phasor_s (Images), spad_lifetime's picture (in ns) and
  /// spad_phasor_plot.
  void finish(std::vector<SensorOutput>& outputs);

 private:
  enum Status : uint8_t { kFitted, kFewCounts, kNotConverged };

  const int32_t height_, width_;
  const double minCounts_;
  const std::string colormap_;
  const FlimFitter fitter_;
  const FlimPhasor phasor_;
  // Written by pixel() from several threads, each pixel by one only.
  mutable std::vector<float> lifetime_, sigma_, g_, s_;
  mutable std::vector<uint8_t> status_;
};

}  // namespace tofsim::sensors::detail
