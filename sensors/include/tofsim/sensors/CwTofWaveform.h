#pragma once
// A measured CW-ToF correlation waveform (the config's `correlation:`), and
// its exact mean over a phase interval, as the built-in sine and square have
// (binCorrelation). Model: sensors/README.md, "Measured correlation waveforms".

#include <complex>
#include <cstddef>
#include <string>
#include <vector>

namespace tofsim::sensors {

/// One period of the correlation rho(theta) of illumination and reference, in
/// one of two forms (exactly one is non-empty). Only its shape is used: the
/// mean is removed and the rest scaled to max |rho| = 1 (CwTofParams'
/// `modulation_contrast` sets the AC amplitude), so any units will do.
struct CorrelationWaveform {
  /// Fourier form: rho(theta) = sum_{k=1..K} Re(c_k e^{i k theta}), c_k =
  /// harmonics[k - 1] (no k = 0 term: the mean is not part of the shape).
  std::vector<std::complex<double>> harmonics;
  /// Samples form: values at phases_rad (strictly increasing, in [0, 2 pi)),
  /// linear in between and periodic: the last sample joins the first at its
  /// phase + 2 pi.
  std::vector<double> phases_rad;
  std::vector<double> values;
  std::string file;  ///< the file it was read from (metadata); empty when inline

  bool fourier() const { return !harmonics.empty(); }
};

/// The most harmonics (K) and samples (M) a waveform may have: each bin's
/// mean costs O(K) (a harmonic's closed form) and the scale's search
/// O(K log K); a measured correlation has a few dozen of either.
inline constexpr std::size_t kMaxHarmonics = 4096;
inline constexpr std::size_t kMaxSamples = 65536;

/// Why w cannot be used (empty when it can): more than kMaxHarmonics or
/// kMaxSamples, no form or both, a value not finite, phases not increasing in [0, 2 pi), or no AC part (zero energy).
std::string waveformProblem(const CorrelationWaveform& w);

/// A waveform ready to integrate: mean removed, scaled to max |rho| = 1.
class PhaseCorrelation {
 public:
  /// Throws InputError with waveformProblem's text.
  explicit PhaseCorrelation(const CorrelationWaveform& w);

  /// The mean of rho over the phase interval [a, b] (rad, a <= b), exact:
  /// each harmonic's closed-form integral, or the linear pieces' areas.
  double mean(double a, double b) const;
  /// rho(theta).
  double value(double theta) const;
  /// The scale the waveform was divided by (max |rho - mean| of the input).
  double scale() const { return scale_; }

 private:
  double fourierMean(double a, double b) const;
  double samplesMean(double a, double b) const;

  std::vector<std::complex<double>> c_;  // Fourier, scaled
  std::vector<double> x_, y_;            // samples: knots x_0 .. x_M = x_0 + 2 pi, scaled values
  double scale_ = 1.0;
};

}  // namespace tofsim::sensors
