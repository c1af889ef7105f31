#include "SpadArrayEvents.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

namespace {

// A pixel's next event in the global order; `version` tells a current entry
// from one its pixel has since replaced (an earlier arrival, or a firing).
struct Entry {
  Moment at;
  uint32_t pixel = 0;
  uint32_t version = 0;
};

// Min-heap order: time, then pixel (a total order among current entries).
bool later(const Entry& a, const Entry& b) {
  if (a.at < b.at) return false;
  if (b.at < a.at) return true;
  return a.pixel > b.pixel;
}

std::vector<std::array<int32_t, 2>> neighbourOffsets(bool eight) {
  std::vector<std::array<int32_t, 2>> offsets;
  for (int32_t dy = -1; dy <= 1; ++dy)
    for (int32_t dx = -1; dx <= 1; ++dx)
      if ((dy != 0 || dx != 0) && (eight || dy == 0 || dx == 0)) offsets.push_back({dy, dx});
  return offsets;
}

class ArrayDriver {
 public:
  ArrayDriver(int32_t width, int32_t height, const std::vector<std::vector<double>>& flux,
              const std::vector<std::vector<double>>& accept, uint64_t cycles,
              const DetectorLaws& laws, const CrosstalkLaw& crosstalk, std::vector<Rng>& rngs,
              std::vector<std::vector<double>>& h)
      : width_(width),
        height_(height),
        cycles_(cycles),
        crosstalk_(crosstalk),
        offsets_(neighbourOffsets(crosstalk.eightNeighbours)),
        accept_(accept),
        rngs_(rngs),
        h_(h) {
    const auto n = static_cast<std::size_t>(width) * height;
    TOFSIM_CHECK(width >= 1 && height >= 1 && flux.size() == n && rngs.size() == n &&
                 h.size() == n && (accept.empty() || accept.size() == n));
    TOFSIM_CHECK(crosstalk.probability >= 0.0 && crosstalk.probability <= 1.0 &&
                 crosstalk.delayBins >= 0.0);
    detectors_.reserve(n);
    for (std::size_t px = 0; px < n; ++px) {
      TOFSIM_CHECK(h[px].size() == flux[px].size() && flux[px].size() == flux[0].size());
      TOFSIM_CHECK(accept.empty() || accept[px].empty() || accept[px].size() == flux[px].size());
      detectors_.emplace_back(flux[px], laws, cycles);
    }
    scheduled_.resize(n);
    version_.assign(n, 0);
  }

  void run() {
    for (std::size_t px = 0; px < detectors_.size(); ++px) schedule(px);
    while (!queue_.empty()) {
      std::pop_heap(queue_.begin(), queue_.end(), later);
      const Entry top = queue_.back();
      queue_.pop_back();
      if (top.version != version_[top.pixel]) continue;  // replaced since
      const std::size_t px = top.pixel;
      const Event e = scheduled_[px];
      detectors_[px].fire(e, rngs_[px], h_[px]);
      if (crosstalk_.probability > 0.0) send(px, e.at);
      schedule(px);
    }
  }

 private:
  // The pixel's next event into the queue (none once past the last cycle).
  void schedule(std::size_t px) {
    scheduled_[px] = detectors_[px].next(rngs_[px]);
    ++version_[px];
    if (scheduled_[px].at.cycle < cycles_) push(px);
  }

  void push(std::size_t px) {
    queue_.push_back({scheduled_[px].at, static_cast<uint32_t>(px), version_[px]});
    std::push_heap(queue_.begin(), queue_.end(), later);
  }

  // The crosstalk of px's avalanche at `at`, drawn from px's stream in a
  // fixed neighbour order: whether each neighbour is hit, its delay, and
  // whether its gate takes the arrival.
  void send(std::size_t px, const Moment& at) {
    Rng& rng = rngs_[px];
    const auto y = static_cast<int32_t>(px / width_), x = static_cast<int32_t>(px % width_);
    const int32_t K = detectors_[px].bins();
    for (const auto& [dy, dx] : offsets_) {
      if (y + dy < 0 || y + dy >= height_ || x + dx < 0 || x + dx >= width_) continue;
      if (!(rng.uniform() < crosstalk_.probability)) continue;
      Moment arrival = at;
      if (crosstalk_.delayBins > 0.0) {  // may run into later cycles, as afterpulses do
        const double t = at.position - crosstalk_.delayBins * std::log1p(-rng.uniform());
        const double wraps = std::floor(t / K);
        if (!(wraps < static_cast<double>(cycles_ - at.cycle))) continue;  // after the end
        arrival = {at.cycle + static_cast<uint64_t>(wraps),
                   std::min(t - wraps * K, std::nextafter(double(K), 0.0))};
      }
      const std::size_t k = static_cast<std::size_t>(y + dy) * width_ + (x + dx);
      if (!accept_.empty() && !accept_[k].empty()) {
        const double g = accept_[k][static_cast<std::size_t>(arrival.position)];
        if (!(g >= 1.0) && !(rng.uniform() < g)) continue;
      }
      SpadDetector& receiver = detectors_[k];
      if (!receiver.canFire(arrival)) continue;  // dead then: lost
      receiver.inject({arrival, EventKind::Crosstalk, static_cast<int64_t>(px)});
      if (arrival < scheduled_[k].at) {
        // next() draws nothing here: the receiver's primary is still valid.
        scheduled_[k] = detectors_[k].next(rngs_[k]);
        ++version_[k];
        push(k);
      }
    }
  }

  const int32_t width_, height_;
  const uint64_t cycles_;
  const CrosstalkLaw crosstalk_;
  const std::vector<std::array<int32_t, 2>> offsets_;
  const std::vector<std::vector<double>>& accept_;
  std::vector<Rng>& rngs_;
  std::vector<std::vector<double>>& h_;
  std::vector<SpadDetector> detectors_;
  std::vector<Event> scheduled_;
  std::vector<uint32_t> version_;
  std::vector<Entry> queue_;  ///< a min-heap (later)
};

}  // namespace

void spadArrayEvents(int32_t width, int32_t height, const std::vector<std::vector<double>>& flux,
                     const std::vector<std::vector<double>>& accept, uint64_t cycles,
                     const DetectorLaws& laws, const CrosstalkLaw& crosstalk,
                     std::vector<Rng>& rngs, std::vector<std::vector<double>>& h) {
  ArrayDriver(width, height, flux, accept, cycles, laws, crosstalk, rngs, h).run();
}

}  // namespace tofsim::sensors::detail
