#include "SpadAfterpulseFlux.h"

#include <algorithm>
#include <cmath>

#include "SpadFreeRunning.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

namespace {
constexpr int64_t kMinIterations = 200;  // cycles at most, or the steady state's budget
constexpr double kTolerance = 1e-12;
constexpr double kSmallStep = 1e-5;  // a change of flux' that q follows by a series

// One trap's releases: an avalanche's in the k-th whole bin after its live
// moment with probability (1 - lambda) lambda^k, `scale` times that in all.
struct Trap {
  double lambda = 0.0, scale = 0.0;
  std::vector<double> powers;  ///< lambda^(i + 1), i in [0, B)
  double periodic = 0.0;       ///< 1 / (1 - lambda^B)
  Trap(double lambda, double scale, std::size_t B) : lambda(lambda), scale(scale), powers(B) {
    double power = 1.0;
    for (double& p : powers) p = power *= lambda;
    periodic = 1.0 / (1.0 - power);
  }
};

// next_i += scale y_i, y_i = sum_{s >= 0} lambda^s x_(i - shift - s), x
// periodic: the avalanches of bin j released s whole bins after the live
// moment j + shift, folded on the cycle. O(B) and one recurrence: p_i =
// x_(i - shift) + lambda p_(i - 1) from p_(-1) = 0 over one cycle; the
// earlier cycles add lambda^(i + 1) y_(-1), and y_(-1) = y_(B - 1) =
// p_(B - 1) / (1 - lambda^B). The index i - shift walks the cycle without a
// modulo per term.
void addFold(const std::vector<double>& x, int64_t shift, const Trap& trap, std::vector<double>& p,
             std::vector<double>& next) {
  const auto B = static_cast<int64_t>(x.size());
  p.resize(x.size());
  double partial = 0.0;
  for (int64_t i = 0, j = ((-shift % B) + B) % B; i < B; ++i, j = j + 1 == B ? 0 : j + 1)
    p[i] = partial = x[j] + trap.lambda * partial;
  const double before = partial * trap.periodic;  // y_(-1)
  for (int64_t i = 0; i < B; ++i) next[i] += trap.scale * (p[i] + trap.powers[i] * before);
}
}  // namespace

const FirstOrderAfterpulses& firstOrderAfterpulses(const std::vector<double>& flux,
                                                   int32_t deadBins, const AfterpulseLaw& law,
                                                   FirstOrderAfterpulses& out) {
  TOFSIM_CHECK(!flux.empty() && deadBins >= 0 && law.delays_bins.size() == law.weights.size());
  const std::size_t K = flux.size();
  out.flux = flux;
  out.detections.assign(K, 0.0);
  double weights = 0.0;
  for (double w : law.weights) weights += w;
  // The detector's steady state is itself a fixed point (a cycle at a time
  // from a live detector, freeRunningProbabilities): rather than reaching it
  // anew for each flux', one detector runs on, each cycle on the flux' that
  // the cycle before gives, until neither flux' nor m changes. Each cycle
  // still has q of its own flux' exactly; only the path to the fixed point
  // differs (the old loop reached each iterate's steady state in ~3 cycles,
  // ~6 iterates: 3x the cycles).
  std::vector<Trap> traps;
  if (law.on()) {
    for (std::size_t c = 0; c < law.delays_bins.size(); ++c) {
      const double lambda = std::exp(-1.0 / law.delays_bins[c]);
      traps.emplace_back(lambda, law.mean * law.weights[c] / weights * (1.0 - lambda), K);
    }
  }
  FreeRunningCycle detector(deadBins);
  std::vector<double> q(K), next, previous(K, -1.0), p;
  const int64_t maxCycles =
      std::max<int64_t>(kMinIterations, kMaxSteadyStateSteps / static_cast<int64_t>(K));
  for (std::size_t i = 0; i < K; ++i) q[i] = -std::expm1(-out.flux[i]);
  for (int64_t n = 0; n < maxCycles; ++n) {
    detector.run(q, out.detections);
    next = flux;
    for (const Trap& trap : traps)
      addFold(out.detections, static_cast<int64_t>(deadBins) + 1, trap, p, next);
    double fluxChange = 0.0, change = 0.0;
    for (std::size_t i = 0; i < K; ++i) {
      fluxChange = std::max(fluxChange, std::fabs(next[i] - out.flux[i]));
      change = std::max(change, std::fabs(out.detections[i] - previous[i]));
    }
    // Converged: detections is the steady state of flux (the last cycle ran
    // on it), and flux' its own image to the tolerance.
    if (fluxChange < kTolerance && change < kSteadyStateTolerance) break;
    // q of the next flux': 1 - e^(-f - d) = q + (1 - q)(1 - e^(-d)). Past
    // the first cycles d is small and three terms of 1 - e^(-d) give it to
    // d^4 / 24 < 5e-22 (an expm1 per bin was a third of the loop's cost).
    for (std::size_t i = 0; i < K; ++i) {
      const double d = next[i] - out.flux[i];
      q[i] = std::fabs(d) < kSmallStep ? q[i] + (1.0 - q[i]) * (d * (1.0 - d * (0.5 - d / 6.0)))
                                       : -std::expm1(-next[i]);
    }
    out.flux.swap(next);
    previous = out.detections;
  }
  return out;
}

}  // namespace tofsim::sensors::detail
