// Exact per-bin correlation, phase estimation and multi-frequency unwrapping.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "tofsim/sensors/CwTof.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
constexpr double kTwoPi = 2.0 * M_PI;
constexpr double kMaxUnwrapPeriods = 64.0;  // cap of the automatic range, in periods of f_min

/// Antiderivative of the triangle wave T (T(0) = 1, T(pi) = -1), periodic
/// because T has zero mean.
double triangleIntegral(double theta) {
  double u = std::fmod(theta, kTwoPi);
  if (u < 0.0) u += kTwoPi;
  return u <= M_PI ? u - u * u / M_PI : u * u / M_PI - 3.0 * u + kTwoPi;
}

double triangle(double theta) {
  double u = std::fmod(theta, kTwoPi);
  if (u < 0.0) u += kTwoPi;
  return u <= M_PI ? 1.0 - 2.0 * u / M_PI : -3.0 + 2.0 * u / M_PI;
}

double wrapPi(double a) { return a - kTwoPi * std::floor((a + M_PI) / kTwoPi); }
}  // namespace

double binCorrelation(Waveform waveform, double frequency_Hz, double phase_rad, double t0_s,
                      double t1_s) {
  TOFSIM_CHECK(waveform != Waveform::Measured);
  const double a = kTwoPi * frequency_Hz * t0_s - phase_rad;
  const double b = kTwoPi * frequency_Hz * t1_s - phase_rad;
  const double width = b - a;
  if (waveform == Waveform::Sine) {
    // (sin b - sin a) / (b - a), written without cancellation.
    if (width == 0.0) return std::cos(a);
    return std::cos(0.5 * (a + b)) * std::sin(0.5 * width) / (0.5 * width);
  }
  if (width < 1e-6) return triangle(0.5 * (a + b));
  // The antiderivative is periodic, so whole periods inside the bin cancel.
  return (triangleIntegral(b) - triangleIntegral(a)) / width;
}

void phaseFromSteps(const double* raw, int32_t steps, double& phase_rad, double& amplitude) {
  double i = 0.0, q = 0.0;
  for (int32_t k = 0; k < steps; ++k) {
    const double phi = kTwoPi * k / steps;
    i += raw[k] * std::cos(phi);
    q += raw[k] * std::sin(phi);
  }
  phase_rad = std::atan2(q, i);
  if (phase_rad < 0.0) phase_rad += kTwoPi;
  amplitude = 2.0 / steps * std::hypot(i, q);
}

double unwrapDepth_m(const std::vector<double>& phases, const std::vector<double>& freqs,
                     double maxDepth_m, double k) {
  TOFSIM_CHECK(!freqs.empty() && phases.size() == freqs.size() && k > 0.0);
  auto depthOf = [&](std::size_t j, double wraps) {
    return (phases[j] + kTwoPi * wraps) * k / (kTwoPi * freqs[j]);
  };
  if (freqs.size() == 1) return depthOf(0, 0.0);
  std::size_t base = 0;
  for (std::size_t j = 1; j < freqs.size(); ++j) {
    if (freqs[j] < freqs[base]) base = j;
  }
  const double baseRange = k / freqs[base];
  const auto candidates = static_cast<int64_t>(std::ceil(maxDepth_m / baseRange));
  double bestCost = std::numeric_limits<double>::infinity(), bestDepth = 0.0;
  for (int64_t n = 0; n < std::max<int64_t>(1, candidates); ++n) {
    const double d = depthOf(base, static_cast<double>(n));
    double cost = 0.0, sum = 0.0, weights = 0.0;
    for (std::size_t j = 0; j < freqs.size(); ++j) {
      const double predicted = kTwoPi * freqs[j] * d / k;
      const double residual = wrapPi(phases[j] - predicted);
      const double dj = d + residual * k / (kTwoPi * freqs[j]);
      cost += (dj - d) * (dj - d);
      sum += freqs[j] * freqs[j] * dj;
      weights += freqs[j] * freqs[j];
    }
    if (cost < bestCost) {
      bestCost = cost;
      bestDepth = sum / weights;
    }
  }
  return bestDepth;
}

double unwrapRange_m(const CwTofParams& p, double k) {
  TOFSIM_CHECK(!p.frequencies_Hz.empty() && k > 0.0);
  double fmin = p.frequencies_Hz[0];
  int64_t g = 0;
  for (double f : p.frequencies_Hz) {
    fmin = std::min(fmin, f);
    g = std::gcd(g, static_cast<int64_t>(std::llround(f / 1e3)));  // kHz resolution
  }
  if (p.max_depth_m > 0.0) return p.max_depth_m;
  const double gcdRange = g > 0 ? k / (1e3 * static_cast<double>(g)) : k / fmin;
  return std::min(gcdRange, kMaxUnwrapPeriods * k / fmin);
}

}  // namespace tofsim::sensors
