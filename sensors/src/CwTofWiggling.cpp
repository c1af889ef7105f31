// The wiggling error of the N-step estimator over a noise-free depth sweep,
// from the waveform alone (no render), and the double-precision phases of a
// pixel the tests compare with the aliasing law.
#include <algorithm>
#include <array>
#include <cmath>

#include "CwTofCorrelator.h"
#include "CwTofOutputs.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

std::vector<double> wigglingError_m(const CwTofParams& p, double k) {
  TOFSIM_CHECK(!p.frequencies_Hz.empty() && p.phase_steps >= 3 && k > 0.0);
  const int32_t N = p.phase_steps, S = kWigglingSweepPoints;
  std::vector<double> errors, raw(N);
  errors.reserve(p.frequencies_Hz.size() * S);
  for (std::size_t f = 0; f < p.frequencies_Hz.size(); ++f) {
    const FrequencyCorrelation rho(p, f);
    const double fHz = p.frequencies_Hz[f], range = k / fHz;
    for (int32_t j = 0; j < S; ++j) {
      const double delay = (j + 0.5) / (S * fHz);
      // A delta at `delay`: the zero-width bin [delay, delay]. The DC part
      // 0.5 (E + ambient) and the contrast move no phase, so they are left out.
      for (int32_t n = 0; n < N; ++n) raw[n] = rho.bin(2.0 * M_PI * n / N, delay, delay);
      double phase = 0.0, amplitude = 0.0;
      phaseFromSteps(raw.data(), N, phase, amplitude);
      const double depth = k * phase / (2.0 * M_PI * fHz);
      errors.push_back(wrapSigned(depth - k * delay, range));
    }
  }
  return errors;
}

std::vector<double> noiseFreePhases(const CwTofParams& p, const TimeAxis& axis,
                                    const std::vector<double>& signal, double delay_s) {
  TOFSIM_CHECK_EQ(signal.size(), static_cast<std::size_t>(axis.bins));
  const Correlator correlator(p, axis);
  std::vector<double> raw, phases, amplitudes;
  correlator.taps(signal, 0.0, delay_s, raw);
  correlator.depth(raw, phases, amplitudes, unwrapRange_m(p, axis.depthPerSecond_m_per_s()));
  return phases;
}

// (F, S) and its max |error|, RMS and mean, over all and per frequency.
SensorOutput wigglingErrorOutput(const std::vector<double>& wiggling_m,
                                 const std::vector<double>& frequencies_Hz) {
  const int32_t S = kWigglingSweepPoints;
  SensorOutput o = makeOutput(
      "cwtof_wiggling_error", SensorOutput::Kind::Array,
      {static_cast<int64_t>(frequencies_Hz.size()), S}, {"frequency", "sweep"},
      {wiggling_m.begin(), wiggling_m.end()}, "m",
      "CW-ToF wiggling error: N-step depth - true depth of a noise-free single return swept "
      "over each frequency's unambiguous range (frequency, sweep point)");
  const auto stats = [](const double* e, std::size_t n) {
    double maxAbs = 0.0, sum2 = 0.0, sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      maxAbs = std::max(maxAbs, std::fabs(e[i]));
      sum2 += e[i] * e[i];
      sum += e[i];
    }
    return std::array<double, 3>{maxAbs, std::sqrt(sum2 / n), sum / n};
  };
  const auto all = stats(wiggling_m.data(), wiggling_m.size());
  o.attributes = {{"sweep_points", S}, {"max_abs_error_m", all[0]}, {"rms_error_m", all[1]}};
  for (std::size_t f = 0; f < frequencies_Hz.size(); ++f) {
    const std::string label = frequencyLabel(frequencies_Hz[f]);
    const auto one = stats(wiggling_m.data() + f * S, S);
    o.attributes.push_back({"max_abs_error_" + label + "_m", one[0]});
    o.attributes.push_back({"rms_error_" + label + "_m", one[1]});
    o.attributes.push_back({"mean_error_" + label + "_m", one[2]});
  }
  o.signed_values = true;
  return o;
}

}  // namespace tofsim::sensors
