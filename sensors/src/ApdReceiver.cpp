#include "ApdReceiver.h"

#include <algorithm>
#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
constexpr double kElectronCharge_C = 1.602176634e-19;

// The standard deviation of x_t - (the mean of samples [a0, a1) and [b0,
// b1)) over a sample's, x = h * w for white w: the combination c (1 at t,
// -1 / cells on the training cells) convolved with the filter h, its
// squares' sum over h's.
double cfarKappa(const BinKernel& h, int32_t a0, int32_t a1, int32_t b0, int32_t b1, int32_t t) {
  const int32_t cells = (a1 - a0) + (b1 - b0);
  if (cells == 0) return 1.0;
  const int32_t lo = std::min(a0, t), hi = std::max(b1 - 1, t);  // c's support
  const auto L = static_cast<int32_t>(h.weights.size());
  std::vector<double> ch(static_cast<std::size_t>(hi - lo + L), 0.0);
  const auto add = [&](int32_t k, double c) {
    for (int32_t j = 0; j < L; ++j) ch[k - lo + j] += c * h.weights[j];
  };
  add(t, 1.0);
  for (int32_t k = a0; k < a1; ++k) add(k, -1.0 / cells);
  for (int32_t k = b0; k < b1; ++k) add(k, -1.0 / cells);
  double num = 0.0, den = 0.0;
  for (double v : ch) num += v * v;
  for (double w : h.weights) den += w * w;
  return std::sqrt(num / den);
}
}  // namespace

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
  rx.electronCurrent_A = q * p.gain / dt;
  rx.electronVariance_A2 = q * q * p.gain * p.gain * rx.excessNoise / (dt * dt) * sumSquares;
  rx.surfaceMean_A = q * ns / dt;
  rx.floorVariance_A2 = (q * q * ns / (dt * dt) +
                         p.tia_noise_A_per_rtHz * p.tia_noise_A_per_rtHz / (2.0 * dt)) *
                        sumSquares;
  if (p.threshold_mode == ApdThreshold::CaCfar) {
    rx.cfarZ = normalUpperQuantile(p.false_alarm);
    rx.cfarKappa.resize(static_cast<std::size_t>(rx.axis.bins));
    const int32_t G = p.cfar_guard_cells, N = p.cfar_training_cells, T = rx.axis.bins;
    const int32_t reach = G + N;
    for (int32_t t = 0; t < T; ++t) {
      // Away from the ends every window is the same: work it out once.
      if (t > reach && t < T - 1 - reach && t != reach + 1) {
        rx.cfarKappa[t] = rx.cfarKappa[reach + 1];
        continue;
      }
      rx.cfarKappa[t] = cfarKappa(rx.filter, std::max(0, t - reach), std::max(0, t - G),
                                  std::min(T, t + G + 1), std::min(T, t + reach + 1), t);
    }
  }
  return rx;
}

double apdNoiseSigma_A(const ApdReceiver& rx, double meanCurrent_A) {
  const double electrons =
      rx.electronCurrent_A > 0.0
          ? std::max(0.0, (meanCurrent_A - rx.surfaceMean_A) / rx.electronCurrent_A)
          : 0.0;
  return std::sqrt(rx.floorVariance_A2 + rx.electronVariance_A2 * electrons);
}

void apdThresholds(const ApdParams& p, const ApdReceiver& rx, const std::vector<double>& v,
                   std::vector<double>& out) {
  const auto T = static_cast<int32_t>(v.size());
  if (p.threshold_mode != ApdThreshold::CaCfar) {
    out.assign(v.size(), rx.threshold_A);
    return;
  }
  // Prefix sums: each window's sum in O(1), in one order for any thread.
  std::vector<double> prefix(v.size() + 1, 0.0);
  for (int32_t t = 0; t < T; ++t) prefix[t + 1] = prefix[t] + v[t];
  const int32_t G = p.cfar_guard_cells, N = p.cfar_training_cells;
  out.resize(v.size());
  for (int32_t t = 0; t < T; ++t) {
    const int32_t a0 = std::max(0, t - G - N), a1 = std::max(0, t - G);
    const int32_t b0 = std::min(T, t + G + 1), b1 = std::min(T, t + G + N + 1);
    const int32_t cells = (a1 - a0) + (b1 - b0);
    if (cells == 0) {  // an axis shorter than the guard: the receiver's own CFAR
      out[t] = rx.backgroundMean_A + rx.cfarZ * rx.backgroundSigma_A;
      continue;
    }
    const double mean = (prefix[a1] - prefix[a0] + prefix[b1] - prefix[b0]) / cells;
    out[t] = mean + rx.cfarZ * rx.cfarKappa[t] * apdNoiseSigma_A(rx, mean);
  }
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

std::vector<ApdEcho> apdEchoes(const std::vector<double>& v, const std::vector<double>& threshold,
                               const ApdReceiver& rx, int32_t maxReturns) {
  std::vector<ApdEcho> echoes;
  const auto T = static_cast<int32_t>(v.size());
  for (int32_t t = 0; t < T && static_cast<int32_t>(echoes.size()) < maxReturns;) {
    if (!(v[t] > threshold[t])) {
      ++t;
      continue;
    }
    int32_t peak = t;
    double sum = 0.0, weighted = 0.0;
    for (; t < T && v[t] > threshold[t]; ++t) {
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
