#include "SpadEventEngine.h"

#include <algorithm>
#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

namespace {

// The first bin j >= from with cumulative flux cum[j + 1] - cum[from] > e
// (cum[0] = 0, cum[K] = the cycle's flux, e below the flux left from `from`).
int32_t binWhereFluxReaches(const std::vector<double>& cum, int32_t from, double e) {
  const double target = cum[from] + e;
  const auto it = std::upper_bound(cum.begin() + from + 1, cum.end(), target);
  const auto j = static_cast<int32_t>(it - cum.begin()) - 1;
  return std::min(j, static_cast<int32_t>(cum.size()) - 2);  // rounding at the last edge
}

double exp1(Rng& rng) { return -std::log1p(-rng.uniform()); }

void synchronous(const std::vector<double>& cum, uint64_t cycles, Rng& rng,
                 std::vector<double>& h) {
  const double total = cum.back();
  const double none = std::exp(-total);  // a cycle without a detection
  uint64_t left = cycles;
  while (left > 0) {
    // Empty cycles before the next detection: Geometric(1 - none).
    if (none > 0.0) {
      const double skip = std::floor(std::log1p(-rng.uniform()) / std::log(none));
      if (!(skip < static_cast<double>(left))) break;
      left -= static_cast<uint64_t>(skip);
    }
    --left;
    // The detection, given one: Exp(1) truncated to the cycle's flux.
    const double e = -std::log1p(-rng.uniform() * -std::expm1(-total));
    h[binWhereFluxReaches(cum, 0, std::min(e, std::nextafter(total, 0.0)))] += 1.0;
  }
}

// A moment of the free-running detector: a cycle and a position in it, in
// bins (bin = floor(position)).
struct Moment {
  uint64_t cycle = 0;
  double position = 0.0;
  bool operator<(const Moment& o) const {
    return cycle < o.cycle || (cycle == o.cycle && position < o.position);
  }
};

// The next photon detection of a detector live from the start of bin `bin`
// of `cycle`; nothing (cycle = `cycles`) when it falls after the last cycle.
Moment nextPhoton(const std::vector<double>& flux, const std::vector<double>& cum, uint64_t cycle,
                  int32_t bin, uint64_t cycles, Rng& rng) {
  const double total = cum.back();
  double e = exp1(rng);
  const double rest = total - cum[bin];
  if (e >= rest) {  // not in this cycle: skip whole cycles of flux
    e -= rest;
    const double whole = std::floor(e / total);
    if (!(whole < static_cast<double>(cycles - cycle - 1))) return {cycles, 0.0};
    cycle += 1 + static_cast<uint64_t>(whole);
    e = std::min(e - whole * total, std::nextafter(total, 0.0));
    bin = 0;
  }
  const int32_t j = binWhereFluxReaches(cum, bin, e);
  // Where in bin j: the flux is uniform across the bin.
  const double into = flux[j] > 0.0 ? (cum[bin] + e - cum[j]) / flux[j] : 0.0;
  return {cycle, j + std::clamp(into, 0.0, std::nextafter(1.0, 0.0))};
}

void freeRunning(const std::vector<double>& flux, const std::vector<double>& cum, uint64_t cycles,
                 int32_t deadBins, const Afterpulsing& afterpulsing, Rng& rng,
                 std::vector<double>& h) {
  const auto K = static_cast<int32_t>(cum.size()) - 1;
  uint64_t cycle = 0;  // the detector is live from bin `bin` of cycle `cycle`
  int32_t bin = 0;
  bool pending = false;  // an afterpulse of the last avalanche waits
  while (cycle < cycles) {
    Moment next = nextPhoton(flux, cum, cycle, bin, cycles, rng);
    if (pending) {
      // Its delay counts from the end of the hold-off, i.e. from now.
      const double at = bin + afterpulsing.delay_bins * exp1(rng);
      const Moment ap{cycle + static_cast<uint64_t>(at / K), std::fmod(at, double(K))};
      if (ap < next) next = ap;
    }
    if (!(next.cycle < cycles)) break;
    const auto j = static_cast<int32_t>(next.position);
    h[j] += 1.0;
    // The new avalanche clears the traps of the last and may fill them again.
    pending = afterpulsing.probability > 0.0 && rng.uniform() < afterpulsing.probability;
    // Dead in bins j + 1 .. j + deadBins, live again after them.
    const int64_t live = static_cast<int64_t>(j) + deadBins + 1;
    cycle = next.cycle + static_cast<uint64_t>(live / K);
    bin = static_cast<int32_t>(live % K);
  }
}

}  // namespace

void spadEvents(const std::vector<double>& flux, uint64_t cycles, int32_t deadBins, Rng& rng,
                std::vector<double>& h, const Afterpulsing& afterpulsing) {
  TOFSIM_CHECK(afterpulsing.probability == 0.0 || deadBins >= 0);
  TOFSIM_CHECK(!flux.empty() && h.size() == flux.size());
  std::vector<double> cum(flux.size() + 1, 0.0);
  for (std::size_t i = 0; i < flux.size(); ++i) {
    TOFSIM_CHECK(flux[i] >= 0.0);
    cum[i + 1] = cum[i] + flux[i];
  }
  if (!(cum.back() > 0.0)) return;
  if (deadBins < 0) {
    synchronous(cum, cycles, rng, h);
  } else {
    freeRunning(flux, cum, cycles, deadBins, afterpulsing, rng, h);
  }
}

}  // namespace tofsim::sensors::detail
