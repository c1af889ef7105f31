#include "tofsim/sensors/SensorStream.h"

namespace tofsim::sensors {

VolumeShape shapeOf(const TransientVolume& volume) {
  return {volume.width(), volume.height(), volume.channels(), volume.axis()};
}

PixelSpan wholeVolume(const TransientVolume& volume, const TransientVolume* directOnly) {
  return {0, static_cast<std::size_t>(volume.width()) * volume.height(), volume.data(),
          directOnly ? directOnly->data() : nullptr};
}

}  // namespace tofsim::sensors
