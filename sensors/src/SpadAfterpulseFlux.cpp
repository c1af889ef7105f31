#include "SpadAfterpulseFlux.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "SpadFreeRunning.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

namespace {
constexpr int64_t kMinIterations = 200;  // cycles at most, or the steady state's budget
constexpr double kTolerance = 1e-12;
constexpr double kSmallStep = 1e-5;  // a change of flux' that q follows by a series
constexpr double kSixth = 1.0 / 6.0;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The distance left to a fixed point that a linear iteration approaches by
// `change` a step, `before` the step before: change r / (1 - r), r = change
// / before; infinite unless the changes shrink.
double remaining(double change, double before) {
  if (change == 0.0) return 0.0;
  const double r = change / before;
  return r < 1.0 ? change * r / (1.0 - r) : kInfinity;
}

// max_i |a_i - b_i|, in four independent maxima (one would wait on each).
double largestChange(const std::vector<double>& a, const std::vector<double>& b) {
  double m[4] = {0.0, 0.0, 0.0, 0.0};
  const std::size_t n = a.size(), whole = n / 4 * 4;
  for (std::size_t i = 0; i < whole; i += 4)
    for (std::size_t k = 0; k < 4; ++k) m[k] = std::max(m[k], std::fabs(a[i + k] - b[i + k]));
  for (std::size_t i = whole; i < n; ++i) m[0] = std::max(m[0], std::fabs(a[i] - b[i]));
  return std::max(std::max(m[0], m[1]), std::max(m[2], m[3]));
}

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

// next_i += scale y_i for each trap, y_i = sum_{s >= 0} lambda^s
// x_(i - shift - s), x periodic: the avalanches of bin j released s whole
// bins after the live moment j + shift, folded on the cycle. O(B) and one
// recurrence: p_i = x_(i - shift) + lambda p_(i - 1) from p_(-1) = 0 over
// one cycle; the earlier cycles add lambda^(i + 1) y_(-1), and y_(-1) =
// y_(B - 1) = p_(B - 1) / (1 - lambda^B). The traps go in pairs (an even
// count: a last one of scale 0 adds +0), whose two recurrences overlap; the
// index i - shift walks the cycle without a modulo per term.
void addFolds(const std::vector<double>& x, int64_t shift, const std::vector<Trap>& traps,
              std::vector<double>& p, std::vector<double>& next) {
  const auto B = static_cast<int64_t>(x.size());
  p.resize(2 * x.size());
  double* pa = p.data();
  double* pb = pa + B;
  for (std::size_t c = 0; c < traps.size(); c += 2) {
    const Trap& a = traps[c];
    const Trap& b = traps[c + 1];
    double partialA = 0.0, partialB = 0.0;
    for (int64_t i = 0, j = ((-shift % B) + B) % B; i < B; ++i, j = j + 1 == B ? 0 : j + 1) {
      pa[i] = partialA = x[j] + a.lambda * partialA;
      pb[i] = partialB = x[j] + b.lambda * partialB;
    }
    const double beforeA = partialA * a.periodic, beforeB = partialB * b.periodic;  // y_(-1)
    for (int64_t i = 0; i < B; ++i) {
      next[i] += a.scale * (pa[i] + a.powers[i] * beforeA);
      next[i] += b.scale * (pb[i] + b.powers[i] * beforeB);
    }
  }
}

// A measured delay table's releases, `kernel` folded on the cycle: kernel[r]
// = mean sum_w P(r + wB <= delay < r + wB + 1), so next_i += sum_r kernel[r]
// x_(i - shift - r), a direct circular convolution, O(B x the table's span in
// bins, at most B) per cycle (no recurrence: the table has no closed form).
std::vector<double> foldedTableKernel(const AfterpulseLaw& law, std::size_t B) {
  const std::vector<double> masses = tableBinMasses(law);
  std::vector<double> kernel(std::min(B, masses.size()), 0.0);
  for (std::size_t s = 0; s < masses.size(); ++s) kernel[s % B] += law.mean * masses[s];
  return kernel;
}

void addTableFold(const std::vector<double>& x, int64_t shift, const std::vector<double>& kernel,
                  std::vector<double>& next) {
  const auto B = static_cast<int64_t>(x.size());
  for (std::size_t r = 0; r < kernel.size(); ++r) {
    const double c = kernel[r];
    if (c == 0.0) continue;
    // next_i += c x_(i - o), o = (shift + r) mod B: two runs without a modulo.
    const int64_t o = (shift + static_cast<int64_t>(r)) % B;
    for (int64_t i = 0; i < o; ++i) next[i] += c * x[i - o + B];
    for (int64_t i = o; i < B; ++i) next[i] += c * x[i - o];
  }
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
  // the cycle before gives, until neither flux' nor m changes (~7 cycles;
  // reaching each iterate's steady state anew took ~3 cycles for each of ~6
  // iterates, and 3 more for the draws).
  std::vector<Trap> traps;
  std::vector<double> tableKernel;
  if (law.on() && law.tabled()) {
    tableKernel = foldedTableKernel(law, K);
  } else if (law.on()) {
    for (std::size_t c = 0; c < law.delays_bins.size(); ++c) {
      const double lambda = std::exp(-1.0 / law.delays_bins[c]);
      traps.emplace_back(lambda, law.mean * law.weights[c] / weights * (1.0 - lambda), K);
    }
    if (traps.size() % 2 == 1) traps.emplace_back(0.0, 0.0, K);  // addFolds' pairs
  }
  FreeRunningCycle detector(deadBins);
  std::vector<double> q(K), next, previous(K, -1.0), p;
  const int64_t maxCycles =
      std::max<int64_t>(kMinIterations, kMaxSteadyStateSteps / static_cast<int64_t>(K));
  for (std::size_t i = 0; i < K; ++i) q[i] = -std::expm1(-out.flux[i]);
  double previousFluxChange = 0.0, previousChange = 0.0;
  for (int64_t n = 0; n < maxCycles; ++n) {
    detector.run(q, out.detections);
    next = flux;
    addFolds(out.detections, static_cast<int64_t>(deadBins) + 1, traps, p, next);
    if (!tableKernel.empty()) {
      addTableFold(out.detections, static_cast<int64_t>(deadBins) + 1, tableKernel, next);
    }
    const double fluxChange = largestChange(next, out.flux);
    const double change = largestChange(out.detections, previous);
    // Converged: detections is the steady state of flux (the last cycle ran
    // on it), and flux' its own image, each to its tolerance. The changes
    // shrink geometrically (by ~30 a cycle here: the afterpulse mean times
    // what a change of flux' does to m), so the distance left to the fixed
    // point is change r / (1 - r), r the last two changes' ratio: that is
    // what must be below the tolerance (it saves a cycle of ~7). The first
    // cycle's change of m (from no detections) counts for nothing.
    const double flux = n >= 1 ? remaining(fluxChange, previousFluxChange) : fluxChange;
    const double steady = n >= 2 ? remaining(change, previousChange) : change;
    if (flux < kTolerance && steady < kSteadyStateTolerance) return out;
    previousFluxChange = fluxChange;
    previousChange = change;
    // q of the next flux': 1 - e^(-f - d) = q + (1 - q)(1 - e^(-d)). Past
    // the first cycles every |d| is below 1e-5 and three terms of 1 - e^(-d)
    // give it to d^4 / 24 < 5e-22 (an expm1 per bin was a third of the
    // loop's cost); before, the expm1.
    if (fluxChange < kSmallStep) {
      for (std::size_t i = 0; i < K; ++i) {
        const double d = next[i] - out.flux[i];
        q[i] += (1.0 - q[i]) * (d * (1.0 - d * (0.5 - d * kSixth)));
      }
    } else {
      for (std::size_t i = 0; i < K; ++i) q[i] = -std::expm1(-next[i]);
    }
    out.flux.swap(next);
    previous.swap(out.detections);  // written whole by the next cycle
  }
  out.detections.swap(previous);  // not converged: the last cycle's
  return out;
}

}  // namespace tofsim::sensors::detail
