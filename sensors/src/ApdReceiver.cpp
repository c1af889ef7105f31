#include "ApdReceiver.h"

#include <algorithm>
#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
constexpr double kElectronCharge_C = 1.602176634e-19;
}

double apdExcessNoise(double gain, double k) { return k * gain + (1.0 - k) * (2.0 - 1.0 / gain); }

double apdResponsivity_A_per_W(const Radiometry& r) {
  if (!(r.wavelength_m > 0.0)) return 0.0;
  const Radiometry perWatt{.quantum_efficiency = r.quantum_efficiency, .wavelength_m = r.wavelength_m};
  return kElectronCharge_C * perWatt.photoelectronsPerUnit();
}

double apdFilterSigma_s(double bandwidth_Hz) {
  // |H(f)| = exp(-2 pi^2 sigma^2 f^2) is 1/sqrt(2) at f = B.
  return bandwidth_Hz > 0.0 ? std::sqrt(std::log(2.0)) / (2.0 * M_PI * bandwidth_Hz) : 0.0;
}

double normalUpperQuantile(double p) {
  TOFSIM_CHECK(p > 0.0 && p < 1.0);
  // Bisection on the tail 0.5 erfc(z / sqrt 2): decreasing in z; 200 halvings
  // reach double precision for any p a config can hold.
  double lo = -40.0, hi = 40.0;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * std::max(1.0, std::fabs(lo)); ++i) {
    const double mid = 0.5 * (lo + hi);
    (0.5 * std::erfc(mid / std::sqrt(2.0)) > p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

ApdReceiver apdReceiver(const ApdParams& p, const TimeAxis& render) {
  ApdReceiver rx;
  rx.axis = resolveBins(p.bins, render);
  const double dt = rx.axis.bin_width_s;
  rx.pulse = gaussianKernel(fwhmToSigma(p.pulse_fwhm_s), dt);
  rx.filter = gaussianKernel(apdFilterSigma_s(p.bandwidth_Hz), dt);
  double sumSquares = 0.0;
  for (double w : rx.filter.weights) sumSquares += w * w;
  rx.noiseBandwidth_Hz = sumSquares / (2.0 * dt);
  rx.excessNoise = apdExcessNoise(p.gain, p.ionization_ratio);
  // Per sample without signal (apdSamples' moments): electrons n_b multiplied
  // and n_s not, white TIA noise of variance i_n^2 / (2 dt), all filtered.
  const double q = kElectronCharge_C;
  const double nb = (p.background_rate + p.dark_current_bulk_A / q) * dt;
  const double ns = p.dark_current_surface_A / q * dt;
  rx.backgroundMean_A = q * (p.gain * nb + ns) / dt;
  const double white = q * q * (p.gain * p.gain * rx.excessNoise * nb + ns) / (dt * dt) +
                       p.tia_noise_A_per_rtHz * p.tia_noise_A_per_rtHz / (2.0 * dt);
  rx.backgroundSigma_A = std::sqrt(white * sumSquares);
  rx.threshold_A = p.threshold_mode == ApdThreshold::Fixed
                       ? p.threshold_A
                       : rx.backgroundMean_A +
                             rx.backgroundSigma_A * normalUpperQuantile(p.false_alarm);
  return rx;
}

namespace detail {

void apdSamples(const ApdParams& p, const ApdReceiver& rx, const std::vector<double>& signal_e,
                Rng& rng, ApdScratch& s, std::vector<double>& out_A) {
  const int32_t T = rx.axis.bins;
  const double dt = rx.axis.bin_width_s, q = kElectronCharge_C;
  s.pulsed.assign(T, 0.0);
  convolveConserving(signal_e.data(), T, 1, rx.pulse, s.pulsed.data());
  const double nb = (p.background_rate + p.dark_current_bulk_A / q) * dt;
  const double ns = p.dark_current_surface_A / q * dt;
  const double thermal = p.tia_noise_A_per_rtHz / std::sqrt(2.0 * dt);
  const double spread = rx.excessNoise - 1.0;  // gain variance / M^2 per electron
  s.current.assign(T, 0.0);
  for (int32_t t = 0; t < T; ++t) {
    const auto primaries = static_cast<double>(rng.poisson(std::max(0.0, s.pulsed[t]) + nb));
    double charge = p.gain * primaries;
    if (spread > 0.0 && primaries > 0.0) {
      charge = p.gain * spread * rng.gamma(primaries / spread);
    }
    if (ns > 0.0) charge += static_cast<double>(rng.poisson(ns));
    s.current[t] = q * charge / dt + (thermal > 0.0 ? thermal * rng.normal() : 0.0);
  }
  out_A.assign(T, 0.0);
  convolveConserving(s.current.data(), T, 1, rx.filter, out_A.data());
  if (p.adc_bits > 0) {
    const double levels = std::ldexp(1.0, p.adc_bits);
    const double lsb = p.adc_full_scale_A / levels;
    for (double& v : out_A) v = std::clamp(std::floor(v / lsb + 0.5), 0.0, levels - 1.0) * lsb;
  }
}

std::vector<ApdEcho> apdEchoes(const std::vector<double>& v, const ApdReceiver& rx,
                               int32_t maxReturns) {
  std::vector<ApdEcho> echoes;
  const auto T = static_cast<int32_t>(v.size());
  for (int32_t t = 0; t < T && static_cast<int32_t>(echoes.size()) < maxReturns;) {
    if (!(v[t] > rx.threshold_A)) {
      ++t;
      continue;
    }
    int32_t peak = t;
    double sum = 0.0, weighted = 0.0;
    for (; t < T && v[t] > rx.threshold_A; ++t) {
      if (v[t] > v[peak]) peak = t;
      sum += v[t];
      weighted += v[t] * rx.axis.binCenter_s(t);
    }
    const double time = weighted / sum;
    const double amplitude = v[peak];
    echoes.push_back({rx.axis.depthOf_m(time), amplitude});
  }
  return echoes;
}

}  // namespace detail
}  // namespace tofsim::sensors
