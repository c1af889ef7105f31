#include "tofsim/sensors/CwTofCaptureOrder.h"

namespace tofsim::sensors {

namespace {

// The pattern's block order (frequency of block b) and its one step order,
// or false when it is not frequency-major with one step order.
bool splitPattern(const std::vector<CwTofCaptureStep>& pattern, int32_t F, int32_t N,
                  std::vector<int32_t>& blocks, std::vector<int32_t>& steps) {
  if (F < 1 || N < 1 || pattern.size() != static_cast<std::size_t>(F) * N) return false;
  for (int32_t b = 0; b < F; ++b) {
    const int32_t f = pattern[static_cast<std::size_t>(b) * N].frequency;
    blocks.push_back(f);
    for (int32_t k = 0; k < N; ++k) {
      const CwTofCaptureStep& s = pattern[static_cast<std::size_t>(b) * N + k];
      if (s.frequency != f) return false;
      if (b == 0) steps.push_back(s.step);
      if (s.step != steps[k]) return false;
    }
  }
  return true;
}

bool isAscending(const std::vector<int32_t>& order) {
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (order[i] != static_cast<int32_t>(i)) return false;
  }
  return true;
}

bool isDescendingFromZero(const std::vector<int32_t>& order) {
  const auto n = static_cast<int32_t>(order.size());
  for (int32_t i = 0; i < n; ++i) {
    if (order[i] != (n - i) % n) return false;
  }
  return true;
}

// The order on `count` items: the pattern's own for its own count, else
// ascending, or descending from 0 when `mirrored` allows and it is so.
std::optional<std::vector<int32_t>> carried(const std::vector<int32_t>& order, int32_t count,
                                            bool mirrored) {
  if (static_cast<int32_t>(order.size()) == count) return order;
  std::vector<int32_t> out;
  if (isAscending(order)) {
    for (int32_t i = 0; i < count; ++i) out.push_back(i);
    return out;
  }
  if (mirrored && isDescendingFromZero(order)) {
    for (int32_t i = 0; i < count; ++i) out.push_back((count - i) % count);
    return out;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::vector<CwTofCaptureStep>> deriveCwTofCaptureOrder(
    const std::vector<CwTofCaptureStep>& pattern, int32_t presetFrequencies, int32_t presetSteps,
    int32_t frequencies, int32_t steps) {
  if (frequencies < 1 || steps < 1) return std::nullopt;
  std::vector<int32_t> blocks, stepOrder;
  if (!splitPattern(pattern, presetFrequencies, presetSteps, blocks, stepOrder)) {
    return std::nullopt;
  }
  const auto f = carried(blocks, frequencies, false);
  const auto n = carried(stepOrder, steps, true);
  if (!f || !n) return std::nullopt;
  std::vector<CwTofCaptureStep> order;
  for (int32_t b : *f) {
    for (int32_t k : *n) order.push_back({b, k});
  }
  return order;
}

std::string cwtofCaptureOrderText(const std::vector<CwTofCaptureStep>& order) {
  std::string text = "[";
  for (std::size_t i = 0; i < order.size(); ++i) {
    text += (i ? ", [" : "[") + std::to_string(order[i].frequency) + ", " +
            std::to_string(order[i].step) + "]";
  }
  return text + "]";
}

}  // namespace tofsim::sensors
