#include "ResponseClasses.h"

#include <algorithm>
#include <utility>

#include "tofsim/util/Error.h"

namespace tofsim::cpu {

void ResponseClasses::configure(std::vector<std::vector<physics::ResponseTaps>> delayed,
                                std::size_t pixels, int32_t bins) {
  stages_ = std::move(delayed);
  cascades_ = std::any_of(stages_.begin(), stages_.end(),
                          [](const std::vector<physics::ResponseTaps>& s) { return s.size() > 1; });
  pixels_ = stages_.empty() ? 0 : pixels;
  bins_ = bins;
  diff_ = util::ZeroedBuffer<double>(stages_.size() * pixels_ * static_cast<std::size_t>(bins) * 3);
  first_.assign(stages_.size() * pixels_, bins);
}

double* ResponseClasses::diffOf(std::size_t i, uint32_t responseClass) {
  const std::size_t slot = (responseClass - 1) * pixels_ + i;
  return diff_.data() + slot * static_cast<std::size_t>(bins_) * 3;
}

void ResponseClasses::deposit(std::size_t i, uint32_t responseClass, const glm::vec3& kernel,
                              const glm::vec3& energy, physics::OffAxisSums& lost) {
  TOFSIM_CHECK(responseClass >= 1 && responseClass <= stages_.size() && i < pixels_);
  physics::depositWide(diffOf(i, responseClass), bins_, kernel, energy, lost);
  int32_t& first = first_[(responseClass - 1) * pixels_ + i];
  first = std::min(first, physics::footprintKnotBin(kernel, 0, bins_));
}

void ResponseClasses::integrateInto(std::size_t i, float* histogram, physics::OffAxisSums& lost) {
  // A cascade's intermediate outputs: one pixel at a time per thread (the
  // memory plan counts GL's scratch region, which is more).
  thread_local std::vector<double> scratch;
  if (cascades_) scratch.resize(static_cast<std::size_t>(bins_) * 3);
  for (std::size_t c = 0; c < stages_.size(); ++c) {
    int32_t& first = first_[c * pixels_ + i];
    if (first >= bins_) continue;
    double* diff = diffOf(i, static_cast<uint32_t>(c + 1));
    const double past =
        physics::applyResponse(diff, scratch.data(), bins_, first, stages_[c], histogram);
    if (past > 0.0) lost.after += static_cast<float>(past);
    // applyResponse left the bin integrals (or a stage's output) from
    // `first` on: zero while in cache.
    std::fill(diff + static_cast<std::size_t>(first) * 3, diff + static_cast<std::size_t>(bins_) * 3,
              0.0);
    first = bins_;
  }
}

void ResponseClasses::clear() {
  for (std::size_t c = 0; c < stages_.size(); ++c) {
    for (std::size_t i = 0; i < pixels_; ++i) {
      int32_t& first = first_[c * pixels_ + i];
      if (first >= bins_) continue;
      double* diff = diffOf(i, static_cast<uint32_t>(c + 1));
      std::fill(diff + static_cast<std::size_t>(first) * 3,
                diff + static_cast<std::size_t>(bins_) * 3, 0.0);
      first = bins_;
    }
  }
}

}  // namespace tofsim::cpu
