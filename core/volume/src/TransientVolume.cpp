#include "tofsim/volume/TransientVolume.h"

#include <utility>

#include "tofsim/util/Error.h"

namespace tofsim {

TransientVolume::TransientVolume(int32_t width, int32_t height, TimeAxis axis,
                                 std::vector<std::string> channels)
    : width_(width), height_(height), axis_(axis), channelNames_(std::move(channels)) {
  TOFSIM_CHECK(width_ > 0 && height_ > 0 && axis_.bins > 0 && !channelNames_.empty());
  data_.assign(static_cast<std::size_t>(width_) * height_ * pixelStride(), 0.0f);
}

Image steadyImage(const TransientVolume& volume) {
  Image image(volume.width(), volume.height(), volume.channels());
  for (int32_t y = 0; y < volume.height(); ++y) {
    for (int32_t x = 0; x < volume.width(); ++x) {
      for (int32_t c = 0; c < volume.channels(); ++c) {
        double sum = 0.0;
        for (int32_t t = 0; t < volume.bins(); ++t) sum += volume.at(y, x, t, c);
        image.at(y, x, c) = static_cast<float>(sum);
      }
    }
  }
  return image;
}

}  // namespace tofsim
