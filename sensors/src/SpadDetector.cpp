#include "SpadDetector.h"

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

// Where in bin j the cumulative flux reaches `target`: the flux is uniform
// across the bin.
double positionIn(const std::vector<double>& flux, const std::vector<double>& cum, int32_t j,
                  double target) {
  const double into = flux[j] > 0.0 ? (target - cum[j]) / flux[j] : 0.0;
  return j + std::clamp(into, 0.0, std::nextafter(1.0, 0.0));
}

// Min-heap order of the pending events.
bool later(const Event& a, const Event& b) { return b.at < a.at; }

}  // namespace

bool deadTimeEndsInItsCycle(const std::vector<double>& flux, int32_t deadBins) {
  auto last = static_cast<int64_t>(flux.size()) - 1;
  while (last >= 0 && !(flux[last] > 0.0)) --last;
  return last + deadBins < static_cast<int64_t>(flux.size());
}

SpadDetector::SpadDetector(const std::vector<double>& flux, const DetectorLaws& laws,
                           uint64_t cycles)
    : flux_(flux),
      cum_(flux.size() + 1, 0.0),
      laws_(laws),
      cycles_(cycles),
      K_(static_cast<int32_t>(flux.size())),
      liveFrom_{0, 0.0},
      primary_{{cycles, 0.0}},
      stopCycle_(cycles) {
  TOFSIM_CHECK(K_ > 0 && laws.deadBins >= 0 && laws.stops >= 0);
  const AfterpulseLaw& ap = laws.afterpulses;
  TOFSIM_CHECK(ap.mean >= 0.0 && (ap.count == AfterpulseLaw::Count::Poisson || ap.mean <= 1.0));
  TOFSIM_CHECK(!ap.delays_bins.empty() && ap.delays_bins.size() == ap.weights.size());
  double weights = 0.0;
  for (std::size_t k = 0; k < ap.delays_bins.size(); ++k) {
    TOFSIM_CHECK(ap.delays_bins[k] >= 0.0 && ap.weights[k] >= 0.0);
    weights += ap.weights[k];
  }
  TOFSIM_CHECK(weights > 0.0);
  if (ap.tabled()) {
    TOFSIM_CHECK(ap.table_cdf.size() >= 2 && ap.table_edges_bins.size() == ap.table_cdf.size());
    TOFSIM_CHECK(ap.table_edges_bins[0] >= 0.0 && ap.table_cdf.front() == 0.0 &&
                 ap.table_cdf.back() == 1.0);
  }
  for (double& w : laws_.afterpulses.weights) w /= weights;
  for (int32_t i = 0; i < K_; ++i) {
    TOFSIM_CHECK(flux[i] >= 0.0);
    cum_[i + 1] = cum_[i] + flux[i];
  }
  quietAfterStops_ =
      !ap.on() && !laws.everyAvalanche && deadTimeEndsInItsCycle(flux, laws.deadBins);
}

Event SpadDetector::next(Rng& rng) {
  const Event none{{cycles_, 0.0}};
  if (!(liveFrom_.cycle < cycles_)) return none;
  popStale();
  if (!primaryValid_) {
    primary_ = {nextPrimary(rng), EventKind::Primary};
    primaryValid_ = true;
  }
  const Event& first =
      !pending_.empty() && pending_.front().at < primary_.at ? pending_.front() : primary_;
  return first.at.cycle < cycles_ ? first : none;
}

void SpadDetector::inject(const Event& e) {
  if (!canFire(e.at) || !(e.at.cycle < cycles_)) return;  // dead then, or after the end: lost
  pending_.push_back(e);
  std::push_heap(pending_.begin(), pending_.end(), later);
}

bool SpadDetector::fire(const Event& e, Rng& rng, std::vector<double>& h) {
  TOFSIM_CHECK(canFire(e.at) && e.at.cycle < cycles_);
  if (e.kind != EventKind::Primary) {
    TOFSIM_CHECK(!pending_.empty() && !(e.at < pending_.front().at));
    std::pop_heap(pending_.begin(), pending_.end(), later);
    pending_.pop_back();
  }
  primaryValid_ = false;  // drawn from a moment now past: drawn again from the next live one
  const auto j = static_cast<int32_t>(e.at.position);
  if (e.at.cycle != stopCycle_) {
    stopCycle_ = e.at.cycle;
    stopsUsed_ = 0;
  }
  const bool recorded = laws_.stops == 0 || stopsUsed_ < laws_.stops;
  if (recorded) {
    h[j] += 1.0;
    ++stopsUsed_;
  }
  // Dead in the rest of bin j and bins j + 1 .. j + deadBins.
  const int64_t live = static_cast<int64_t>(j) + laws_.deadBins + 1;
  liveFrom_ = {e.at.cycle + static_cast<uint64_t>(live / K_), static_cast<double>(live % K_)};
  if (quietAfterStops_ && laws_.stops > 0 && stopsUsed_ >= laws_.stops &&
      liveFrom_.cycle == e.at.cycle) {
    liveFrom_ = {e.at.cycle + 1, 0.0};  // nothing left in this cycle can matter
  }
  if (laws_.afterpulses.on()) {
    if (laws_.afterpulses.reset) {
      pending_.erase(std::remove_if(pending_.begin(), pending_.end(),
                                    [](const Event& p) { return p.kind == EventKind::Afterpulse; }),
                     pending_.end());
      std::make_heap(pending_.begin(), pending_.end(), later);
    }
    queueAfterpulses(rng);
  }
  return recorded;
}

Moment SpadDetector::nextPrimary(Rng& rng) const {
  const double total = cum_.back();
  if (!(total > 0.0)) return {cycles_, 0.0};
  const auto bin = static_cast<int32_t>(liveFrom_.position);
  TOFSIM_CHECK(bin == liveFrom_.position);  // live again at a bin's start
  if (laws_.stops > 0 && bin == 0) return firstOfCleanCycles(rng);
  uint64_t cycle = liveFrom_.cycle;
  int32_t from = bin;
  double e = exp1(rng);
  const double rest = total - cum_[bin];
  if (e >= rest) {  // not in this cycle: skip whole cycles of flux
    e -= rest;
    const double whole = std::floor(e / total);
    if (!(whole < static_cast<double>(cycles_ - cycle - 1))) return {cycles_, 0.0};
    cycle += 1 + static_cast<uint64_t>(whole);
    e = std::min(e - whole * total, std::nextafter(total, 0.0));
    from = 0;
  }
  const int32_t j = binWhereFluxReaches(cum_, from, e);
  return {cycle, positionIn(flux_, cum_, j, cum_[from] + e)};
}

// From a cycle's start: the cycles without a primary before the next one,
// Geometric(1 - e^-total), then its place given one, Exp(1) truncated to the
// cycle's flux (the synchronous mode's draws since the first engine).
Moment SpadDetector::firstOfCleanCycles(Rng& rng) const {
  const double total = cum_.back();
  const double none = std::exp(-total);  // a cycle without a primary
  uint64_t cycle = liveFrom_.cycle;
  if (none > 0.0) {
    const double skip = std::floor(std::log1p(-rng.uniform()) / std::log(none));
    if (!(skip < static_cast<double>(cycles_ - cycle))) return {cycles_, 0.0};
    cycle += static_cast<uint64_t>(skip);
  }
  const double e =
      std::min(-std::log1p(-rng.uniform() * -std::expm1(-total)), std::nextafter(total, 0.0));
  const int32_t j = binWhereFluxReaches(cum_, 0, e);
  return {cycle, positionIn(flux_, cum_, j, e)};
}

void SpadDetector::queueAfterpulses(Rng& rng) {
  const AfterpulseLaw& ap = laws_.afterpulses;
  const uint64_t n = ap.count == AfterpulseLaw::Count::Poisson
                         ? rng.poisson(ap.mean)
                         : static_cast<uint64_t>(rng.uniform() < ap.mean);
  for (uint64_t k = 0; k < n; ++k) {
    // Its delay counts from the end of the hold-off, i.e. from liveFrom_.
    double delay = 0.0;
    if (ap.tabled()) {
      delay = tableDelay(ap, rng.uniform());
    } else {
      std::size_t c = 0;  // the trap level: by its weight
      if (ap.weights.size() > 1) {
        double u = rng.uniform();
        while (c + 1 < ap.weights.size() && u >= ap.weights[c]) u -= ap.weights[c++];
      }
      delay = ap.delays_bins[c] * exp1(rng);
    }
    const double at = liveFrom_.position + delay;
    const double wraps = std::floor(at / K_);
    if (!(wraps < static_cast<double>(cycles_ - liveFrom_.cycle))) continue;  // after the end
    const double position = std::min(at - wraps * K_, std::nextafter(double(K_), 0.0));
    pending_.push_back(
        {{liveFrom_.cycle + static_cast<uint64_t>(wraps), position}, EventKind::Afterpulse});
    std::push_heap(pending_.begin(), pending_.end(), later);
  }
}

void SpadDetector::popStale() {
  while (!pending_.empty() && pending_.front().at < liveFrom_) {
    std::pop_heap(pending_.begin(), pending_.end(), later);
    pending_.pop_back();
  }
}

}  // namespace tofsim::sensors::detail
