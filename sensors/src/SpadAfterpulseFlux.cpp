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

// y_i = sum_{s >= 0} lambda^s x_(i - shift - s), x periodic: the avalanches
// of bin j released s whole bins after the live moment j + shift, folded on
// the cycle. O(B): y_0 summed once over a cycle (the later cycles fold in
// 1 / (1 - lambda^B)), then y_i = x_(i - shift) + lambda y_(i - 1).
void geometricFold(const std::vector<double>& x, int64_t shift, double lambda,
                   std::vector<double>& y) {
  const auto B = static_cast<int64_t>(x.size());
  // The index i - shift - s on the cycle, walked down (y_0) and up (y_i)
  // without a modulo per term.
  const int64_t start = ((-shift % B) + B) % B;  // (0 - shift) mod B
  double y0 = 0.0, power = 1.0;
  for (int64_t s = 0, j = start; s < B; ++s, power *= lambda, j = j == 0 ? B - 1 : j - 1)
    y0 += power * x[j];
  y.resize(x.size());  // written whole below
  y[0] = y0 / (1.0 - power);
  for (int64_t i = 1, j = start + 1 == B ? 0 : start + 1; i < B; ++i, j = j + 1 == B ? 0 : j + 1)
    y[i] = x[j] + lambda * y[i - 1];
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
  FreeRunningCycle detector(deadBins);
  std::vector<double> q(K), next, previous(K, -1.0), y;
  const int64_t maxCycles =
      std::max<int64_t>(kMinIterations, kMaxSteadyStateSteps / static_cast<int64_t>(K));
  for (int64_t n = 0; n < maxCycles; ++n) {
    for (std::size_t i = 0; i < K; ++i) q[i] = -std::expm1(-out.flux[i]);
    detector.run(q, out.detections);
    next = flux;
    if (law.on()) {
      for (std::size_t c = 0; c < law.delays_bins.size(); ++c) {
        // Released in the k-th whole bin after the live moment: (1 - lambda) lambda^k.
        const double lambda = std::exp(-1.0 / law.delays_bins[c]);
        geometricFold(out.detections, static_cast<int64_t>(deadBins) + 1, lambda, y);
        const double scale = law.mean * law.weights[c] / weights * (1.0 - lambda);
        for (std::size_t i = 0; i < K; ++i) next[i] += scale * y[i];
      }
    }
    double fluxChange = 0.0, change = 0.0;
    for (std::size_t i = 0; i < K; ++i) {
      fluxChange = std::max(fluxChange, std::fabs(next[i] - out.flux[i]));
      change = std::max(change, std::fabs(out.detections[i] - previous[i]));
    }
    // Converged: detections is the steady state of flux (the last cycle ran
    // on it), and flux' its own image to the tolerance.
    if (fluxChange < kTolerance && change < kSteadyStateTolerance) break;
    out.flux.swap(next);
    previous = out.detections;
  }
  return out;
}

}  // namespace tofsim::sensors::detail
