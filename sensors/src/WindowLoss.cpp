#include "tofsim/sensors/WindowLoss.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <type_traits>
#include <vector>

#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {

bool selectionFits(const ChannelSelection& channel, int32_t channels) {
  if (!channel.weights.empty()) return static_cast<int32_t>(channel.weights.size()) == channels;
  return channel.index == ChannelSelection::kSumOfChannels ||
         (channel.index >= 0 && channel.index < channels);
}

double meterWholeVolume(std::optional<InstrumentWindow> window, const TransientVolume& volume) {
  WindowLossMeter meter(std::move(window), shapeOf(volume));
  meter.consume(wholeVolume(volume));
  return meter.fraction();
}

}  // namespace

std::optional<InstrumentWindow> instrumentWindow(const SensorParams& params) {
  return std::visit([](const auto& p) { return SensorType<std::decay_t<decltype(p)>>::window(p); },
                    params);
}

WindowLossMeter::WindowLossMeter(std::optional<InstrumentWindow> window, const VolumeShape& shape)
    : window_(std::move(window)), shape_(shape) {
  if (!window_) return;
  fits_ = selectionFits(window_->common.channel, shape.channels);
  // Only the magnitudes count (weights of mixed sign must not let light
  // cancel out), and the radiometric scale cancels in a fraction.
  window_->common.radiometry = Radiometry{};
  rowWeight_.assign(static_cast<std::size_t>(shape.height), window_->rows.empty() ? 1 : 0);
  for (int32_t y : window_->rows) {
    if (y >= 0 && y < shape.height) ++rowWeight_[y];
  }
  perBin_.assign(static_cast<std::size_t>(shape.axis.bins), 0.0);
}

void WindowLossMeter::consume(const PixelSpan& span) {
  if (!window_ || !fits_) return;
  for (std::size_t i = 0; i < span.pixelCount; ++i) {
    const int32_t weight = rowWeight_[(span.firstPixel + i) / shape_.width];
    if (weight == 0) continue;
    pixelSignal(span.volume + i * shape_.pixelFloats(), shape_.axis.bins, shape_.channels,
                window_->common, signal_);
    for (std::size_t t = 0; t < perBin_.size(); ++t) perBin_[t] += weight * std::abs(signal_[t]);
  }
}

double WindowLossMeter::fraction() const {
  if (!window_ || !fits_) return 0.0;
  const double total = std::accumulate(perBin_.begin(), perBin_.end(), 0.0);
  if (!(total > 0.0)) return 0.0;
  std::vector<double> kept;
  resampleEnergy(perBin_, shape_.axis, resolveBins(window_->bins, shape_.axis), kept);
  const double inside = std::accumulate(kept.begin(), kept.end(), 0.0);
  return std::clamp(1.0 - inside / total, 0.0, 1.0);
}

double instrumentWindowLoss(const SensorCommon& common, const InstrumentBins& bins,
                            const std::vector<int32_t>& rows, const TransientVolume& volume) {
  return meterWholeVolume(InstrumentWindow{common, bins, rows}, volume);
}

double windowLossFraction(const SensorParams& params, const TransientVolume& volume) {
  return meterWholeVolume(instrumentWindow(params), volume);
}

}  // namespace tofsim::sensors
