#include "SpadFlux.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "SpadParamsCheck.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace detail {

namespace {
// The measured response's first sample edge, relative to its time zero.
double irfStart_s(const SpadIrf& irf) {
  return irf.first_time_s - 0.5 * irf.sample_width_s - irfTimeZero_s(irf);
}

// Pulse and jitter, both Gaussian: their sum's sigma.
double pulseJitterSigma_s(const SpadParams& p) {
  const double sp = fwhmToSigma(p.pulse_fwhm_s);
  const double sj = fwhmToSigma(p.jitter_fwhm_s);
  return std::sqrt(sp * sp + sj * sj);
}
}  // namespace

BinKernel spadKernel(const SpadParams& p, const TimeAxis& axis) {
  if (p.irf.present()) {
    const SpadIrf& irf = p.irf;
    return piecewiseConstantKernel(irf.values, irfStart_s(irf), irf.sample_width_s,
                                   axis.bin_width_s);
  }
  return gaussianTailKernel(pulseJitterSigma_s(p), p.jitter_tail_fraction, p.jitter_tail_s,
                            axis.bin_width_s);
}

KernelSupport spadKernelSupport(const SpadParams& p) {
  if (p.irf.present()) {
    return piecewiseConstantSupport(p.irf.values.size(), irfStart_s(p.irf), p.irf.sample_width_s);
  }
  return gaussianTailSupport(pulseJitterSigma_s(p), p.jitter_tail_fraction, p.jitter_tail_s);
}

// With a DNL table the light is first spread over the nominal bins (where the
// kernel is defined), then moved into the true unequal bins by overlap.
void fluxFromSignal(const std::vector<double>& signal, const TimeAxis& render, const SpadParams& p,
                    const SpadPixel& pixel, const TdcBins& bins, const BinKernel& kernel,
                    std::vector<double>& resampled, std::vector<double>& flux) {
  const TimeAxis& axis = bins.axis;
  resampleEnergy(signal, render, axis, resampled);
  flux.assign(resampled.size(), 0.0);
  convolveConserving(resampled.data(), axis.bins, 1, kernel, flux.data());
  const double pde = pixel.pde, dcr_per_s = pixel.dcr_per_s;
  if (bins.edges.empty()) {
    const double background =
        pde * p.ambient_rate_per_s * axis.bin_width_s + dcr_per_s * axis.bin_width_s;
    for (double& f : flux) f = pde * std::max(0.0, f) + background;
    return;
  }
  resampled.swap(flux);
  resampleEnergyToEdges(resampled, axis, bins.edges, flux);
  for (int32_t i = 0; i < axis.bins; ++i) {
    const double w = bins.width(i);
    flux[i] = pde * std::max(0.0, flux[i]) + pde * p.ambient_rate_per_s * w + dcr_per_s * w;
  }
}

// A disarmed detector sees nothing, so the first-photon and dead-time laws
// run on the gated flux alone.
void gateFlux(const SpadParams& p, const SpadGate& gate, const SpadPixel& pixel,
              const TdcBins& bins, std::vector<double>& flux) {
  if (p.gate_width_s > 0.0) applyGate(gate.shifted(pixel.gate_skew_s), bins, flux);
}

}  // namespace detail

void spadFluxPerCycle(const TransientVolume& volume, const SpadParams& params, const TimeAxis& axis,
                      int32_t y, int32_t x, std::vector<double>& flux) {
  detail::checkSpadParams(params);
  std::vector<double> signal, resampled;
  pixelSignal(volume, params.common, y, x, signal);
  const std::size_t px = static_cast<std::size_t>(y) * volume.width() + x;
  const SpadPixel pixel = spadPixel(params, px);
  const detail::TdcBins bins = detail::tdcBins(params, axis);
  detail::fluxFromSignal(signal, volume.axis(), params, pixel, bins,
                         detail::spadKernel(params, axis), resampled, flux);
  detail::gateFlux(params, detail::spadGate(params), pixel, bins, flux);
}

double irfTimeZero_s(const SpadIrf& irf) {
  TOFSIM_CHECK(irf.present());
  const auto timeOf = [&](std::size_t k) {
    return irf.first_time_s + static_cast<double>(k) * irf.sample_width_s;
  };
  switch (irf.t0) {
    case SpadIrf::TimeZero::Peak:
      return timeOf(static_cast<std::size_t>(
          std::max_element(irf.values.begin(), irf.values.end()) - irf.values.begin()));
    case SpadIrf::TimeZero::Centroid: {
      double sum = 0.0, moment = 0.0;
      for (std::size_t k = 0; k < irf.values.size(); ++k) {
        sum += irf.values[k];
        moment += irf.values[k] * timeOf(k);
      }
      return moment / sum;
    }
    case SpadIrf::TimeZero::Time:
      return irf.t0_s;
  }
  return irf.t0_s;
}

}  // namespace tofsim::sensors
