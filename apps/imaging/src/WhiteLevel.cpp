#include "tofsim/imaging/WhiteLevel.h"

#include <algorithm>
#include <cmath>

namespace tofsim::imaging {

namespace {
constexpr std::size_t kMaxSamples = std::size_t{1} << 22;
}  // namespace

WhiteLevelSampler::WhiteLevelSampler(std::size_t count)
    : step_(std::max<std::size_t>(1, count / kMaxSamples)) {}

void WhiteLevelSampler::add(const float* values, std::size_t n) {
  for (; next_ < fed_ + n; next_ += step_) {
    const float v = values[next_ - fed_];
    if (v > 0.0f && std::isfinite(v)) samples_.push_back(v);
  }
  fed_ += n;
}

double WhiteLevelSampler::white() {
  if (samples_.empty()) return 1.0;
  const std::size_t k =
      std::min(samples_.size() - 1, static_cast<std::size_t>(0.995 * samples_.size()));
  std::nth_element(samples_.begin(), samples_.begin() + static_cast<long>(k), samples_.end());
  return samples_[k];
}

}  // namespace tofsim::imaging
