#include "tofsim/lidar/Echoes.h"

#include <algorithm>
#include <cmath>

namespace tofsim::lidar {

namespace {

// The echo of the nonzero bins b[0 .. n): energy, and the energy-weighted
// mean time (zero bins add nothing to either: the dense run's sums).
Echo echoOf(const WaveformBin* b, std::size_t n, const TimeAxis& axis, double legs) {
  Echo e;
  e.first_bin = b[0].bin;
  e.last_bin = b[n - 1].bin;
  double weighted = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    e.intensity += b[i].value;
    weighted += double(b[i].value) * axis.binCenter_s(b[i].bin);
  }
  e.time_s = e.intensity > 0.0 ? weighted / e.intensity : axis.binCenter_s(e.first_bin);
  e.range_m = axis.speedOfLight_m_per_s() * e.time_s / legs;
  return e;
}

std::size_t strongestOf(const std::vector<Echo>& echoes, std::size_t skip) {
  std::size_t best = echoes.size();
  for (std::size_t i = 0; i < echoes.size(); ++i) {
    if (i == skip) continue;
    if (best == echoes.size() || echoes[i].intensity > echoes[best].intensity) best = i;
  }
  return best;
}

}  // namespace

std::vector<Echo> findEchoes(const WaveformBin* bins, std::size_t count, const TimeAxis& axis,
                             const ReturnSettings& returns) {
  const double legs = axis.camera_unwarp ? 1.0 : 2.0;
  // The separation as bins of optical path: range x eta x legs.
  const double gap_m = returns.separation_m * axis.index_of_refraction * legs;
  const auto gapBins = static_cast<int32_t>(std::ceil(gap_m / axis.bin_width_m()));
  std::vector<Echo> echoes;
  std::size_t first = count, last = count;  // entries: an echo is [first, last]
  for (std::size_t i = 0; i < count; ++i) {
    if (!(bins[i].value > returns.threshold)) continue;
    if (first < count && bins[i].bin - bins[last].bin > gapBins) {
      echoes.push_back(echoOf(bins + first, last - first + 1, axis, legs));
      first = count;
    }
    if (first == count) first = i;
    last = i;
  }
  if (first < count) echoes.push_back(echoOf(bins + first, last - first + 1, axis, legs));
  return echoes;
}

std::vector<Echo> findEchoes(const float* waveform, const TimeAxis& axis,
                             const ReturnSettings& returns) {
  std::vector<WaveformBin> bins;
  for (int32_t b = 0; b < axis.bins; ++b) {
    if (waveform[b] != 0.0f) bins.push_back({b, waveform[b]});
  }
  return findEchoes(bins.data(), bins.size(), axis, returns);
}

std::vector<Echo> selectReturns(const std::vector<Echo>& echoes, const ReturnSettings& returns) {
  std::vector<Echo> kept;
  if (echoes.empty() || returns.max < 1) return kept;
  switch (returns.mode) {
    case ReturnMode::First:
      kept = {echoes.front()};
      break;
    case ReturnMode::Last:
      kept = {echoes.back()};
      break;
    case ReturnMode::Strongest:
      kept = {echoes[strongestOf(echoes, echoes.size())]};
      break;
    case ReturnMode::Dual: {
      const std::size_t strongest = strongestOf(echoes, echoes.size());
      const std::size_t last = echoes.size() - 1;
      kept = {echoes[strongest]};
      const std::size_t second = strongest != last ? last : strongestOf(echoes, strongest);
      if (second < echoes.size()) kept.push_back(echoes[second]);
      break;
    }
    case ReturnMode::All:
      kept = echoes;
      break;
  }
  if (kept.size() > static_cast<std::size_t>(returns.max)) kept.resize(returns.max);
  return kept;
}

}  // namespace tofsim::lidar
