// A measured correlation waveform: its shape (mean removed, max |rho| = 1)
// and its exact mean over a phase interval, per harmonic in closed form or
// per linear piece.
#include "tofsim/sensors/CwTofWaveform.h"

#include <algorithm>
#include <cmath>

#include "tofsim/optics/Fft.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
constexpr double kTwoPi = 2.0 * M_PI;

double fourierValue(const std::vector<std::complex<double>>& c, double theta) {
  double sum = 0.0;
  for (std::size_t k = 1; k <= c.size(); ++k) {
    const double arg = static_cast<double>(k) * theta;
    sum += c[k - 1].real() * std::cos(arg) - c[k - 1].imag() * std::sin(arg);
  }
  return sum;
}

/// rho at the N phases 2 pi j / N at once (N a power of two > K): Re sum_k
/// c_k e^{2 pi i k j / N} is the real part of the forward transform of the
/// conjugate coefficients. O(N log N), where evaluating each phase by itself
/// is O(N K), quadratic in K for a grid that grows with K.
std::vector<double> fourierOnGrid(const std::vector<std::complex<double>>& c, int N) {
  std::vector<std::complex<double>> x(static_cast<std::size_t>(N), 0.0);
  for (std::size_t k = 1; k <= c.size(); ++k) x[k] = std::conj(c[k - 1]);
  optics::fourierTransform(x);
  std::vector<double> rho(x.size());
  for (std::size_t j = 0; j < x.size(); ++j) rho[j] = x[j].real();
  return rho;
}

/// max |rho| of a Fourier series: exact for one harmonic, else the best of a
/// dense grid (at least 64 points per period of the highest harmonic)
/// polished by Newton steps on rho' = 0 (to ~1e-15; the scale only sets the
/// amplitude, never a phase).
double fourierMaxAbs(const std::vector<std::complex<double>>& c) {
  int nonzero = 0;
  double only = 0.0;
  for (const auto& ck : c) {
    if (ck != 0.0) {
      ++nonzero;
      only = std::abs(ck);
    }
  }
  if (nonzero <= 1) return only;
  const int grid = optics::powerOfTwoAtLeast(std::max<int>(1024, 64 * static_cast<int>(c.size())));
  const std::vector<double> rho = fourierOnGrid(c, grid);
  int bestIndex = 0;
  for (int i = 1; i < grid; ++i) {
    if (std::fabs(rho[i]) > std::fabs(rho[bestIndex])) bestIndex = i;
  }
  const double bestTheta = kTwoPi * bestIndex / grid;
  // The grid's best evaluated directly, as the Newton steps' values are.
  double best = std::fabs(fourierValue(c, bestTheta));
  double theta = bestTheta;
  for (int iter = 0; iter < 8; ++iter) {
    double d1 = 0.0, d2 = 0.0;
    for (std::size_t k = 1; k <= c.size(); ++k) {
      const double kd = static_cast<double>(k), arg = kd * theta;
      const double re = c[k - 1].real() * std::cos(arg) - c[k - 1].imag() * std::sin(arg);
      const double im = c[k - 1].real() * std::sin(arg) + c[k - 1].imag() * std::cos(arg);
      d1 -= kd * im;
      d2 -= kd * kd * re;
    }
    if (d2 == 0.0) break;
    theta -= d1 / d2;
    best = std::max(best, std::fabs(fourierValue(c, theta)));
  }
  return best;
}

/// The mean over a period of the periodic linear interpolant.
double samplesMeanValue(const std::vector<double>& phases, const std::vector<double>& values) {
  const std::size_t M = values.size();
  double area = 0.0;
  for (std::size_t j = 0; j < M; ++j) {
    const double x1 = j + 1 < M ? phases[j + 1] : phases[0] + kTwoPi;
    area += 0.5 * (values[j] + values[(j + 1) % M]) * (x1 - phases[j]);
  }
  return area / kTwoPi;
}
}  // namespace

std::string waveformProblem(const CorrelationWaveform& w) {
  const bool fourier = !w.harmonics.empty(), samples = !w.values.empty();
  if (fourier == samples) return "give either harmonics or samples (exactly one form)";
  if (fourier) {
    if (w.harmonics.size() > kMaxHarmonics) {
      return std::to_string(w.harmonics.size()) + " harmonics: at most " +
             std::to_string(kMaxHarmonics) + " (c_1 .. c_" + std::to_string(kMaxHarmonics) +
             "; higher ones are far beyond what a sensor's correlation holds)";
    }
    for (std::size_t k = 0; k < w.harmonics.size(); ++k) {
      if (!std::isfinite(w.harmonics[k].real()) || !std::isfinite(w.harmonics[k].imag())) {
        return "harmonic " + std::to_string(k + 1) + " is not finite";
      }
    }
    if (!(fourierMaxAbs(w.harmonics) > 0.0)) {
      return "every harmonic is 0: the waveform has no AC part (zero energy), so no phase";
    }
    return "";
  }
  if (w.values.size() > kMaxSamples) {
    return std::to_string(w.values.size()) + " samples: at most " + std::to_string(kMaxSamples) +
           " per period";
  }
  if (w.phases_rad.size() != w.values.size()) {
    return std::to_string(w.values.size()) + " values for " + std::to_string(w.phases_rad.size()) +
           " phases";
  }
  double largest = 0.0;
  for (std::size_t j = 0; j < w.values.size(); ++j) {
    const double p = w.phases_rad[j], v = w.values[j];
    if (!std::isfinite(v)) return "sample " + std::to_string(j) + " is not finite";
    if (!std::isfinite(p) || p < 0.0 || p >= kTwoPi) {
      return "the phase of sample " + std::to_string(j) + " is not in [0, 2 pi)";
    }
    if (j > 0 && !(p > w.phases_rad[j - 1])) {
      return "the phases must increase (sample " + std::to_string(j) + ")";
    }
    largest = std::max(largest, std::fabs(v));
  }
  const double mean = samplesMeanValue(w.phases_rad, w.values);
  double ac = 0.0;
  for (double v : w.values) ac = std::max(ac, std::fabs(v - mean));
  if (!(ac > 1e-12 * largest)) {
    return "the samples are constant: the waveform has no AC part (zero energy), so no phase";
  }
  return "";
}

PhaseCorrelation::PhaseCorrelation(const CorrelationWaveform& w) {
  const std::string problem = waveformProblem(w);
  if (!problem.empty()) throw InputError("cwtof correlation waveform: " + problem);
  if (w.fourier()) {
    scale_ = fourierMaxAbs(w.harmonics);
    for (const auto& ck : w.harmonics) c_.push_back(ck / scale_);
    return;
  }
  const double mean = samplesMeanValue(w.phases_rad, w.values);
  scale_ = 0.0;
  for (double v : w.values) scale_ = std::max(scale_, std::fabs(v - mean));
  x_ = w.phases_rad;
  x_.push_back(w.phases_rad[0] + kTwoPi);
  for (double v : w.values) y_.push_back((v - mean) / scale_);
  y_.push_back(y_[0]);
}

double PhaseCorrelation::value(double theta) const {
  if (!c_.empty()) return fourierValue(c_, theta);
  const double u = x_[0] + (theta - x_[0]) - kTwoPi * std::floor((theta - x_[0]) / kTwoPi);
  std::size_t j = std::upper_bound(x_.begin(), x_.end(), u) - x_.begin();
  j = std::clamp<std::size_t>(j, 1, x_.size() - 1) - 1;
  return y_[j] + (y_[j + 1] - y_[j]) * (u - x_[j]) / (x_[j + 1] - x_[j]);
}

double PhaseCorrelation::mean(double a, double b) const {
  TOFSIM_CHECK(b >= a);
  if (b == a) return value(a);
  return c_.empty() ? samplesMean(a, b) : fourierMean(a, b);
}

// Each harmonic's bin average: Re(c_k e^{i k mid}) sin(k h) / (k h), written
// in the built-in sine's order of operations so that c_1 = 1 alone gives its
// bytes.
double PhaseCorrelation::fourierMean(double a, double b) const {
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  double sum = 0.0;
  for (std::size_t k = 1; k <= c_.size(); ++k) {
    const double kd = static_cast<double>(k), arg = kd * mid, h = kd * half;
    const double re = c_[k - 1].real() * std::cos(arg) - c_[k - 1].imag() * std::sin(arg);
    sum += re * std::sin(h) / h;
  }
  return sum;
}

// Whole periods add nothing (zero mean); the rest is summed piece by piece,
// each linear piece's area exactly (no antiderivative differences to cancel).
double PhaseCorrelation::samplesMean(double a, double b) const {
  const double width = b - a;
  const std::size_t M = x_.size() - 1;
  double remaining = width - kTwoPi * std::floor(width / kTwoPi);
  double pos = x_[0] + (a - x_[0]) - kTwoPi * std::floor((a - x_[0]) / kTwoPi);
  std::size_t j = std::upper_bound(x_.begin(), x_.end(), pos) - x_.begin();
  j = std::clamp<std::size_t>(j, 1, M) - 1;
  const auto at = [&](std::size_t s, double x) {
    return y_[s] + (y_[s + 1] - y_[s]) * (x - x_[s]) / (x_[s + 1] - x_[s]);
  };
  double area = 0.0;
  for (std::size_t guard = 0; remaining > 0.0 && guard <= 2 * M + 2; ++guard) {
    const double step = std::min(remaining, x_[j + 1] - pos);
    area += 0.5 * (at(j, pos) + at(j, pos + step)) * step;
    remaining = step < remaining ? remaining - step : 0.0;
    pos += step;
    if (++j == M) {
      j = 0;
      pos -= kTwoPi;
    }
  }
  return area / width;
}

}  // namespace tofsim::sensors
