#pragma once
// Private to the SPAD model: a pixel's expected detections per cycle in each
// TDC bin before pile-up and dead time (its flux): the rendered signal through
// the instrument response (pulse and jitter, or a measured IRF), with the
// pixel's own PDE and dark counts, on the true bins of a TDC with DNL, then
// through the gate. spadFluxPerCycle (Spad.h) is this for one pixel of a
// volume; the stream runs it per pixel.

#include <vector>

#include "SpadGate.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/sensors/SpadPixelMaps.h"
#include "tofsim/sensors/TimeKernel.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::sensors::detail {

/// Arrival-to-timestamp kernel on `axis`'s bins: the measured IRF (its time
/// zero at 0) or the Gaussian of pulse and jitter with its exponential tail.
BinKernel spadKernel(const SpadParams& p, const TimeAxis& axis);
/// The shifts spadKernel lays out (s), for the check of its width.
KernelSupport spadKernelSupport(const SpadParams& p);

/// Flux per cycle of one pixel from its render bins (signal in
/// photo-electrons) before the gate; `resampled` is scratch.
void fluxFromSignal(const std::vector<double>& signal, const TimeAxis& render, const SpadParams& p,
                    const SpadPixel& pixel, const TdcBins& bins, const BinKernel& kernel,
                    std::vector<double>& resampled, std::vector<double>& flux);

/// `flux` through the pixel's gate (moved by its skew); no gate: unchanged.
void gateFlux(const SpadParams& p, const SpadGate& gate, const SpadPixel& pixel,
              const TdcBins& bins, std::vector<double>& flux);

}  // namespace tofsim::sensors::detail
