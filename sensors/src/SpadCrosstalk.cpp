#include "SpadCrosstalk.h"

#include <algorithm>
#include <cmath>

#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

namespace {
// A hazard of 1 (an arrival certain in this bin) would be an infinite flux:
// 1 - 1e-12 is 27.6 per neighbour, every cycle detects there all the same.
constexpr double kMaxHazard = 1.0 - 1e-12;

BinKernel delayKernel(double delay_s, double binWidth_s) {
  // An exponential delay (no Gaussian part: sigma 0, all of it tail),
  // transferred exactly into bins for an avalanche uniform in its bin.
  return delay_s > 0.0 ? gaussianTailKernel(0.0, 1.0, delay_s, binWidth_s) : BinKernel{};
}
}  // namespace

KernelSupport crosstalkDelaySupport(double delay_s) {
  return delay_s > 0.0 ? gaussianTailSupport(0.0, 1.0, delay_s) : KernelSupport{};
}

SpadCrosstalk::SpadCrosstalk(const SpadParams& p, int32_t bins, double binWidth_s, int32_t deadBins,
                             int32_t width, int32_t height, std::size_t batch)
    : synchronous_(p.mode == SpadMode::Synchronous),
      probability_(p.crosstalk_probability),
      bins_(bins),
      deadBins_(deadBins),
      width_(width),
      height_(height),
      delayed_(p.crosstalk_delay_s > 0.0),
      delay_(delayKernel(p.crosstalk_delay_s, binWidth_s)),
      batch_(std::max<std::size_t>(batch, 1)) {
  TOFSIM_CHECK(bins >= 1 && width >= 1 && height >= 1);
  const bool eight = p.crosstalk_neighbours == CrosstalkNeighbours::Eight;
  for (int32_t dy = -1; dy <= 1; ++dy)
    for (int32_t dx = -1; dx <= 1; ++dx)
      if ((dy != 0 || dx != 0) && (eight || dy == 0 || dx == 0)) offsets_.push_back({dy, dx});
  // Received: the oldest pixel not yet received and W + 1 before it; sent:
  // W + 1 after it, and a batch more.
  const std::size_t slots = batch_ + 2 * static_cast<std::size_t>(width) + 3;
  flux_.resize(std::min(slots, static_cast<std::size_t>(width) * height));
  sent_.resize(flux_.size());
}

void SpadCrosstalk::send(std::size_t px) {
  const std::vector<double>& flux = this->flux(px);
  TOFSIM_CHECK(flux.size() == static_cast<std::size_t>(bins_));
  const std::vector<double> m =
      synchronous_ ? firstPhotonProbabilities(flux) : freeRunningProbabilities(flux, deadBins_);
  std::vector<double>& r = sent_[px % sent_.size()];
  if (!delayed_) {
    r = m;
    return;
  }
  // Synchronous: an arrival after the last bin is lost (the TDC window ends;
  // the next cycle's is not reached to first order). Free-running: the laser
  // period is the TDC range, so it arrives in the next period's bins.
  r.assign(m.size(), 0.0);
  const auto taps = static_cast<int32_t>(delay_.weights.size());
  for (int32_t j = 0; j < bins_; ++j) {
    if (m[j] == 0.0) continue;
    for (int32_t d = 0; d < taps; ++d) {
      int32_t i = j + delay_.first + d;
      if (synchronous_) {
        if (i < 0 || i >= bins_) continue;
      } else {
        i = ((i % bins_) + bins_) % bins_;
      }
      r[i] += m[j] * delay_.weights[d];
    }
  }
}

void SpadCrosstalk::receive(std::size_t px, std::vector<double>& out) const {
  out = flux(px);
  // Per bin, the probability that no neighbour's arrival comes in it (given
  // none before, synchronous): one logarithm per bin for all neighbours. Its
  // rounding, 1e-16 absolute, is far below any flux that matters.
  thread_local std::vector<double> none;
  none.assign(out.size(), 1.0);
  const auto y = static_cast<int32_t>(px / width_), x = static_cast<int32_t>(px % width_);
  for (const auto& [dy, dx] : offsets_) {
    if (y + dy < 0 || y + dy >= height_ || x + dx < 0 || x + dx >= width_) continue;
    const std::size_t k = static_cast<std::size_t>(y + dy) * width_ + (x + dx);
    const std::vector<double>& r = sent_[k % sent_.size()];
    double before = 0.0;  // synchronous: probability of an arrival in an earlier bin
    for (int32_t i = 0; i < bins_; ++i) {
      const double a = probability_ * r[i];
      if (a <= 0.0) continue;
      const double hazard = synchronous_ ? a / std::max(1.0 - before, 1e-300) : a;
      before += a;
      none[i] *= 1.0 - std::min(hazard, kMaxHazard);
    }
  }
  for (int32_t i = 0; i < bins_; ++i)
    if (none[i] < 1.0) out[i] -= std::log(none[i]);
}

std::size_t SpadCrosstalk::receivable(std::size_t sent) const {
  const std::size_t pixels = static_cast<std::size_t>(width_) * height_;
  if (sent >= pixels) return pixels;
  const std::size_t lookAhead = static_cast<std::size_t>(width_) + 1;
  return sent > lookAhead ? sent - lookAhead : 0;
}

}  // namespace tofsim::sensors::detail
