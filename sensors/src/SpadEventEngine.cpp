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

void freeRunning(const std::vector<double>& cum, uint64_t cycles, int32_t deadBins, Rng& rng,
                 std::vector<double>& h) {
  const auto K = static_cast<int32_t>(cum.size()) - 1;
  const double total = cum.back();
  uint64_t cycle = 0;  // the detector is live from bin `bin` of cycle `cycle`
  int32_t bin = 0;
  while (cycle < cycles) {
    double e = exp1(rng);
    const double rest = total - cum[bin];
    if (e >= rest) {  // not in this cycle: skip whole cycles of flux
      e -= rest;
      const double whole = std::floor(e / total);
      if (!(whole < static_cast<double>(cycles - cycle - 1))) break;
      cycle += 1 + static_cast<uint64_t>(whole);
      e -= whole * total;
      bin = 0;
      e = std::min(e, std::nextafter(total, 0.0));
    }
    const int32_t j = binWhereFluxReaches(cum, bin, e);
    h[j] += 1.0;
    // Dead in bins j + 1 .. j + deadBins, live again after them.
    const int64_t next = static_cast<int64_t>(j) + deadBins + 1;
    cycle += static_cast<uint64_t>(next / K);
    bin = static_cast<int32_t>(next % K);
  }
}

}  // namespace

void spadEvents(const std::vector<double>& flux, uint64_t cycles, int32_t deadBins, Rng& rng,
                std::vector<double>& h) {
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
    freeRunning(cum, cycles, deadBins, rng, h);
  }
}

}  // namespace tofsim::sensors::detail
