#pragma once
// Private to the SPAD model: one laser cycle of the free-running detector's
// expected detections, carried over from cycle to cycle, the step that both
// its steady state (freeRunningProbabilities) and the afterpulse flux's fixed
// point (SpadAfterpulseFlux.h) repeat.

#include <cstdint>
#include <vector>

namespace tofsim::sensors::detail {

/// The steady state is reached when no bin's detection probability changes
/// by this much from one cycle to the next.
inline constexpr double kSteadyStateTolerance = 1e-13;
/// Bins simulated at most to reach it.
inline constexpr int64_t kMaxSteadyStateSteps = 4'000'000;

/// The detector's state at a cycle's start: the probability that it is live
/// and the detections of the last deadBins + 1 bins (a ring); live and ring
/// sum to 1. Starts live at the first bin.
class FreeRunningCycle {
 public:
  explicit FreeRunningCycle(int32_t deadBins);

  /// One laser cycle from the current state, q[i] the probability of an
  /// avalanche in bin i when live (1 - e^(-flux_i)): m[i] the probability of
  /// one in bin i (m.size() == q.size()). The detector that fired at step n
  /// is live again at step n + deadBins + 1.
  void run(const std::vector<double>& q, std::vector<double>& m);

 private:
  std::vector<double> ring_;  ///< ring_[n % (deadBins + 1)]: the detection of step n
  double live_ = 1.0;
  int32_t slot_ = 0;  ///< step % (deadBins + 1)
};

}  // namespace tofsim::sensors::detail
