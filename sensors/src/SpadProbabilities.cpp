// Per-cycle detection probabilities of the SPAD model and Coates' estimator.
#include <algorithm>
#include <cmath>

#include "PeakDepth.h"
#include "SpadFreeRunning.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {}  // namespace

std::vector<double> firstPhotonProbabilities(const std::vector<double>& flux) {
  std::vector<double> p(flux.size());
  double survive = 1.0;  // no detection in earlier bins
  for (std::size_t i = 0; i < flux.size(); ++i) {
    const double q = -std::expm1(-flux[i]);
    p[i] = survive * q;
    survive *= 1.0 - q;
  }
  return p;
}

namespace detail {

FreeRunningCycle::FreeRunningCycle(int32_t deadBins)
    : ring_(static_cast<std::size_t>(deadBins) + 1, 0.0) {
  TOFSIM_CHECK(deadBins >= 0);
}

void FreeRunningCycle::run(const std::vector<double>& q, std::vector<double>& m) {
  // The ring's slot is advanced, not taken modulo (a division per bin was
  // most of the cost).
  const auto slots = static_cast<int32_t>(ring_.size());
  const auto K = static_cast<int32_t>(q.size());
  double live = live_;
  int32_t slot = slot_;
  for (int32_t i = 0; i < K; ++i) {
    const int32_t nextSlot = slot + 1 == slots ? 0 : slot + 1;
    m[i] = live * q[i];
    ring_[slot] = m[i];
    live += ring_[nextSlot] - m[i];
    live = std::clamp(live, 0.0, 1.0);
    slot = nextSlot;
  }
  live_ = live;
  slot_ = slot;
}

}  // namespace detail

std::vector<double> freeRunningProbabilities(const std::vector<double>& flux, int32_t deadBins) {
  TOFSIM_CHECK(deadBins >= 0 && !flux.empty());
  const auto K = static_cast<int32_t>(flux.size());
  std::vector<double> q(flux.size());
  for (int32_t i = 0; i < K; ++i) q[i] = -std::expm1(-flux[i]);
  detail::FreeRunningCycle detector(deadBins);
  std::vector<double> m(flux.size(), 0.0), previous(flux.size(), -1.0);
  const int64_t maxCycles = std::max<int64_t>(8, detail::kMaxSteadyStateSteps / K);
  for (int64_t cycle = 0; cycle < maxCycles; ++cycle) {
    detector.run(q, m);
    double change = 0.0;
    for (int32_t i = 0; i < K; ++i) change = std::max(change, std::fabs(m[i] - previous[i]));
    if (change < detail::kSteadyStateTolerance) return m;
    previous.swap(m);  // m is written whole by the next cycle
  }
  return previous;  // the last cycle's
}

bool deadTimeReachesNextCycle(const std::vector<double>& counts, int32_t deadBins) {
  const auto B = static_cast<int64_t>(counts.size());
  for (int64_t j = std::max<int64_t>(0, B - deadBins); j < B; ++j) {
    if (counts[static_cast<std::size_t>(j)] > 0.0) return true;
  }
  return false;
}

std::vector<double> coatesEstimate(const std::vector<double>& counts, int64_t cycles, int64_t stops,
                                   int32_t deadBins) {
  if (stops == 1 && !deadTimeReachesNextCycle(counts, deadBins)) {
    return coatesEstimate(counts, cycles);
  }
  const auto B = static_cast<int64_t>(counts.size());
  // tail[k]: the counts of the cycle's last k bins; wrapped(n): of the n
  // bins before bin 0, going back through as many earlier cycles as needed.
  std::vector<double> tail(static_cast<std::size_t>(B) + 1, 0.0);
  for (int64_t k = 1; k <= B; ++k) tail[k] = tail[k - 1] + counts[static_cast<std::size_t>(B - k)];
  const auto wrapped = [&](int64_t n) {
    return n <= 0 ? 0.0 : static_cast<double>(n / B) * tail[B] + tail[n % B];
  };
  std::vector<double> flux(counts.size(), 0.0);
  double stopped = 0.0;  // one stop: the cycles that stopped before bin i
  double window = 0.0;   // otherwise: the detections of this cycle in the d bins before i
  for (int64_t i = 0; i < B; ++i) {
    const double h = counts[static_cast<std::size_t>(i)];
    const double dead = wrapped(deadBins - i) + (stops == 1 ? stopped : window);
    const double live = static_cast<double>(cycles) - dead;
    if (live > 0.0) flux[static_cast<std::size_t>(i)] = coatesBinFlux(h, live);
    stopped += h;
    window += h;
    if (i - deadBins >= 0) window -= counts[static_cast<std::size_t>(i - deadBins)];
  }
  return flux;
}

std::vector<double> coatesEstimate(const std::vector<double>& counts, int64_t cycles) {
  std::vector<double> flux(counts.size(), 0.0);
  double remaining = static_cast<double>(cycles);
  for (std::size_t i = 0; i < counts.size(); ++i) {
    if (remaining <= 0.0) break;
    flux[i] = coatesBinFlux(counts[i], remaining);
    remaining -= counts[i];
  }
  return flux;
}

}  // namespace tofsim::sensors
