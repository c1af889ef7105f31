#pragma once
// Private to the CW-ToF model: the noise-free raw values of a pixel's
// transient (exact per-bin correlation) and the depth they give.

#include <cmath>
#include <optional>
#include <vector>

#include "tofsim/sensors/CwTof.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

/// One frequency's correlation, built-in or measured: the mean of
/// rho(2 pi f t - phase) over a bin [t0, t1).
class FrequencyCorrelation {
 public:
  FrequencyCorrelation(const CwTofParams& p, std::size_t f)
      : waveform_(p.waveform), f_(p.frequencies_Hz[f]) {
    if (waveform_ != Waveform::Measured) {
      if (!p.correlation.empty()) {
        throw InputError("cwtof correlation waveforms are given but the waveform is not measured");
      }
      return;
    }
    const std::size_t F = p.frequencies_Hz.size(), given = p.correlation.size();
    if (given != 1 && given != F) {
      throw InputError("cwtof measured waveform: " + std::to_string(given) +
                       " correlation waveforms for " + std::to_string(F) +
                       " frequencies (give one for all, or one per frequency)");
    }
    measured_.emplace(p.correlation[given == 1 ? 0 : f]);
  }

  double bin(double phase_rad, double t0_s, double t1_s) const {
    if (!measured_) return binCorrelation(waveform_, f_, phase_rad, t0_s, t1_s);
    // The phases as binCorrelation forms them.
    constexpr double kTwoPi = 2.0 * M_PI;
    return measured_->mean(kTwoPi * f_ * t0_s - phase_rad, kTwoPi * f_ * t1_s - phase_rad);
  }

 private:
  Waveform waveform_;
  double f_;
  std::optional<PhaseCorrelation> measured_;
};

/// Per pixel: the noise-free raw values (F * N) of a volume, and with two
/// taps tap B's too (at the reference phase + pi).
struct Correlator {
  const CwTofParams& p;
  const TimeAxis& axis;
  std::vector<double> table;  // (taps, F, N, T): correlation of each render bin
  std::vector<FrequencyCorrelation> rho;
  std::size_t rows = 0;            // taps * F * N
  std::vector<double> quadrature;  // Sine: (F, 2, T), the bin means of cos and sin of 2 pi f t

  Correlator(const CwTofParams& params, const TimeAxis& a) : p(params), axis(a) {
    const int32_t N = p.phase_steps;
    for (std::size_t fi = 0; fi < p.frequencies_Hz.size(); ++fi) rho.emplace_back(p, fi);
    for (int32_t tap = 0; tap < (p.taps == 2 ? 2 : 1); ++tap) {
      for (const FrequencyCorrelation& r : rho) {
        for (int32_t k = 0; k < N; ++k) {
          const double phi = referencePhase(tap, k);
          for (int32_t t = 0; t < axis.bins; ++t) {
            const double t0 = axis.binStart_s(t);
            table.push_back(r.bin(phi, t0, t0 + axis.bin_width_s));
          }
        }
        rows += N;
      }
    }
    if (p.waveform != Waveform::Sine) return;
    for (std::size_t fi = 0; fi < rho.size(); ++fi) {  // mean cos and sin of 2 pi f t per bin
      for (double phase : {0.0, M_PI / 2}) {
        for (int32_t t = 0; t < axis.bins; ++t) {
          const double t0 = axis.binStart_s(t);
          quadrature.push_back(rho[fi].bin(phase, t0, t0 + axis.bin_width_s));
        }
      }
    }
  }

  /// Tap A: 2 pi k / N; tap B: + pi (the complementary reference).
  double referencePhase(int32_t tap, int32_t k) const {
    const double phi = 2.0 * M_PI * k / p.phase_steps;
    return tap == 0 ? phi : phi + M_PI;
  }

  /// raw[f * N + k] = 0.5 (sum E + ambient) + 0.5 m sum_t E_t rho_t(f, k).
  void raw(const std::vector<double>& signal, double ambient, std::vector<double>& out) const {
    correlate(signal, ambient, p.frequencies_Hz.size() * p.phase_steps, out,
              [&](std::size_t j) { return table.data() + j * signal.size(); });
  }

  /// Every tap's raws (rows: tap A's F * N, then tap B's) of a pixel whose
  /// fixed-pattern time offset is delay_s: each bin's phase interval shifted
  /// by 2 pi f delay_s inside the bin mean, exactly (the table when 0).
  void taps(const std::vector<double>& signal, double ambient, double delay_s,
            std::vector<double>& out) const {
    if (delay_s == 0.0) {
      correlate(signal, ambient, rows, out,
                [&](std::size_t j) { return table.data() + j * signal.size(); });
      return;
    }
    const std::size_t FN = p.frequencies_Hz.size() * p.phase_steps;
    if (!quadrature.empty()) {
      delayedSine(signal, ambient, delay_s, out);
      return;
    }
    std::vector<double> shifted(signal.size());
    correlate(signal, ambient, rows, out, [&](std::size_t j) {
      const std::size_t f = (j % FN) / p.phase_steps;
      const double phi = referencePhase(static_cast<int32_t>(j / FN), j % p.phase_steps);
      for (std::size_t t = 0; t < shifted.size(); ++t) {
        const double t0 = axis.binStart_s(static_cast<int32_t>(t)) + delay_s;
        shifted[t] = rho[f].bin(phi, t0, t0 + axis.bin_width_s);
      }
      return static_cast<const double*>(shifted.data());
    });
  }

  /// taps() of a sine with a delay, in two dot products per frequency: the
  /// bin mean of cos(2 pi f (t + delay) - phi) is cos(psi) C + sin(psi) S,
  /// psi = phi - 2 pi f delay, C and S the bin means of cos and sin of 2 pi f t.
  void delayedSine(const std::vector<double>& signal, double ambient, double delay_s,
                   std::vector<double>& out) const {
    const std::size_t T = signal.size(), F = p.frequencies_Hz.size();
    const std::size_t N = static_cast<std::size_t>(p.phase_steps);
    std::vector<double> dots(2 * F, 0.0);
    for (std::size_t k = 0; k < 2 * F; ++k) {
      const double* q = quadrature.data() + k * T;
      for (std::size_t t = 0; t < T; ++t) dots[k] += signal[t] * q[t];
    }
    out.resize(rows);
    double total = ambient;
    for (double e : signal) total += e;
    const double ac = 0.5 * p.modulation_contrast;
    for (std::size_t j = 0; j < rows; ++j) {
      const std::size_t f = (j % (F * N)) / N;
      const double psi = referencePhase(static_cast<int32_t>(j / (F * N)), j % N) -
                         2.0 * M_PI * p.frequencies_Hz[f] * delay_s;
      out[j] = 0.5 * total + ac * (std::cos(psi) * dots[2 * f] + std::sin(psi) * dots[2 * f + 1]);
    }
  }

  /// Phases and amplitudes (F) from raw values, and the depth: unwrapped
  /// over `range` when F >= 2, the wrapped depth of the one frequency else.
  double depth(const std::vector<double>& raw, std::vector<double>& phases,
               std::vector<double>& amplitudes, double range) const {
    const auto F = static_cast<int32_t>(p.frequencies_Hz.size());
    phases.resize(F);
    amplitudes.resize(F);
    for (int32_t f = 0; f < F; ++f) {
      phaseFromSteps(raw.data() + static_cast<std::size_t>(f) * p.phase_steps, p.phase_steps,
                     phases[f], amplitudes[f]);
    }
    // Delay -> depth in the medium (c / eta), so a scene in water is not
    // reported as (eta - 1) x depth of multipath error.
    return unwrapDepth_m(phases, p.frequencies_Hz, range, axis.depthPerSecond_m_per_s());
  }

  /// The depth depth() gives a noise-free single return at delay_s (a delta:
  /// the zero-width bin [delay_s, delay_s]), as wigglingError_m's sweep: no
  /// multipath, no noise, only the waveform's and the estimator's error. The
  /// DC part moves no phase and is left out.
  double singleReturnDepth(double delay_s, std::vector<double>& raw, std::vector<double>& phases,
                           std::vector<double>& amplitudes, double range) const {
    const int32_t N = p.phase_steps;
    raw.resize(p.frequencies_Hz.size() * N);
    for (std::size_t f = 0; f < p.frequencies_Hz.size(); ++f) {
      for (int32_t n = 0; n < N; ++n) {
        raw[f * N + n] = rho[f].bin(2.0 * M_PI * n / N, delay_s, delay_s);
      }
    }
    return depth(raw, phases, amplitudes, range);
  }

  /// 0.5 (sum E + ambient) + 0.5 m sum_t E_t rho_t for each of `count`
  /// correlation rows, rowOf(j) giving row j's T values.
  template <typename RowOf>
  void correlate(const std::vector<double>& signal, double ambient, std::size_t count,
                 std::vector<double>& out, RowOf&& rowOf) const {
    const std::size_t T = signal.size();
    const double ac = 0.5 * p.modulation_contrast;  // 0.5 exactly at m = 1
    double total = ambient;
    for (double e : signal) total += e;
    out.assign(count, 0.5 * total);
    for (std::size_t j = 0; j < count; ++j) {
      const double* r = rowOf(j);
      double s = 0.0;
      for (std::size_t t = 0; t < T; ++t) s += signal[t] * r[t];
      out[j] += ac * s;
    }
  }

  /// The depth one frequency's phase stands for, in [0, k / f).
  double wrappedDepth(std::size_t f, double phase) const {
    return axis.depthPerSecond_m_per_s() * phase / (2.0 * M_PI * p.frequencies_Hz[f]);
  }
};

/// An error e between two depths measured modulo `range`, folded into
/// [-range/2, range/2]: a whole number of wraps is ambiguity, not multipath.
inline double wrapSigned(double e, double range) { return e - range * std::round(e / range); }

}  // namespace tofsim::sensors
