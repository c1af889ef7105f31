#include "tofsim/sensors/WindowLoss.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <type_traits>
#include <vector>

#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {

bool selectionFits(const ChannelSelection& channel, const TransientVolume& volume) {
  if (!channel.weights.empty()) {
    return static_cast<int32_t>(channel.weights.size()) == volume.channels();
  }
  return channel.index >= 0 && channel.index < volume.channels();
}

// Energy per render bin summed over the given rows (all when empty), as
// magnitudes: weights of mixed sign must not let light cancel out.
std::vector<double> energyPerBin(const SensorCommon& common, const std::vector<int32_t>& rows,
                                 const TransientVolume& volume) {
  SensorCommon unscaled;  // the radiometric scale cancels in a fraction
  unscaled.channel = common.channel;
  std::vector<int32_t> all;
  if (rows.empty()) {
    all.resize(static_cast<std::size_t>(volume.height()));
    std::iota(all.begin(), all.end(), 0);
  }
  std::vector<double> perBin(static_cast<std::size_t>(volume.bins()), 0.0), signal;
  for (int32_t y : rows.empty() ? all : rows) {
    if (y < 0 || y >= volume.height()) continue;
    for (int32_t x = 0; x < volume.width(); ++x) {
      pixelSignal(volume, unscaled, y, x, signal);
      for (std::size_t t = 0; t < perBin.size(); ++t) perBin[t] += std::abs(signal[t]);
    }
  }
  return perBin;
}

}  // namespace

double instrumentWindowLoss(const SensorCommon& common, const InstrumentBins& bins,
                            const std::vector<int32_t>& rows, const TransientVolume& volume) {
  if (!selectionFits(common.channel, volume)) return 0.0;
  const std::vector<double> perBin = energyPerBin(common, rows, volume);
  const double total = std::accumulate(perBin.begin(), perBin.end(), 0.0);
  if (!(total > 0.0)) return 0.0;
  std::vector<double> kept;
  resampleEnergy(perBin, volume.axis(), resolveBins(bins, volume.axis()), kept);
  const double inside = std::accumulate(kept.begin(), kept.end(), 0.0);
  return std::clamp(1.0 - inside / total, 0.0, 1.0);
}

double windowLossFraction(const SensorParams& params, const TransientVolume& volume) {
  return std::visit(
      [&](const auto& p) {
        return SensorType<std::decay_t<decltype(p)>>::windowLossFraction(p, volume);
      },
      params);
}

}  // namespace tofsim::sensors
