#include "tofsim/lidar/Echoes.h"

#include <algorithm>
#include <cmath>

namespace tofsim::lidar {

namespace {

// The echo of bins [first, last]: energy, and the energy-weighted mean time.
Echo echoOf(const float* w, int32_t first, int32_t last, const TimeAxis& axis, double legs) {
  Echo e;
  e.first_bin = first;
  e.last_bin = last;
  double weighted = 0.0;
  for (int32_t b = first; b <= last; ++b) {
    e.intensity += w[b];
    weighted += double(w[b]) * axis.binCenter_s(b);
  }
  e.time_s = e.intensity > 0.0 ? weighted / e.intensity : axis.binCenter_s(first);
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

std::vector<Echo> findEchoes(const float* waveform, const TimeAxis& axis,
                             const ReturnSettings& returns) {
  const double legs = axis.camera_unwarp ? 1.0 : 2.0;
  // The separation as bins of optical path: range x eta x legs.
  const double gap_m = returns.separation_m * axis.index_of_refraction * legs;
  const auto gapBins = static_cast<int32_t>(std::ceil(gap_m / axis.bin_width_m()));
  std::vector<Echo> echoes;
  int32_t first = -1, last = -1;
  for (int32_t b = 0; b < axis.bins; ++b) {
    if (!(waveform[b] > returns.threshold)) continue;
    if (first >= 0 && b - last > gapBins) {
      echoes.push_back(echoOf(waveform, first, last, axis, legs));
      first = -1;
    }
    if (first < 0) first = b;
    last = b;
  }
  if (first >= 0) echoes.push_back(echoOf(waveform, first, last, axis, legs));
  return echoes;
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
