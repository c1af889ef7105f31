#include "tofsim/capture/VolumeCollector.h"

#include <algorithm>

namespace tofsim::capture {

std::vector<std::string> defaultChannelNames(int32_t channels) {
  if (channels == 3) return {"R", "G", "B"};
  std::vector<std::string> names;
  for (int32_t c = 0; c < channels; ++c) names.push_back("C" + std::to_string(c));
  return names;
}

VolumeCollector::VolumeCollector(int32_t width, int32_t height, const TimeAxis& axis,
                                 int32_t channels, int32_t bounceCount)
    : direct(width, height, axis, defaultChannelNames(channels)),
      indirect(width, height, axis, defaultChannelNames(channels)) {
  for (int32_t k = 0; k < bounceCount; ++k) bounces.push_back(indirect);
}

void VolumeCollector::consume(const Segment& segment) {
  const std::size_t offset = segment.firstPixel * direct.pixelStride();
  const std::size_t floats = segment.pixelCount * direct.pixelStride();
  std::copy_n(segment.component(kDirect), floats, direct.data() + offset);
  std::copy_n(segment.component(kIndirect), floats, indirect.data() + offset);
  for (std::size_t k = 0; k < bounces.size(); ++k) {
    const float* bounce = segment.component(bounceComponent(static_cast<int32_t>(k) + 1));
    std::copy_n(bounce, floats, bounces[k].data() + offset);
  }
}

TransientVolume VolumeCollector::total() const {
  TransientVolume sum = direct;
  for (std::size_t i = 0; i < sum.size(); ++i) sum.data()[i] += indirect.data()[i];
  return sum;
}

}  // namespace tofsim::capture
