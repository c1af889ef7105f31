#include "tofsim/sensors/SensorStream.h"

namespace tofsim::sensors {

VolumeShape shapeOf(const TransientVolume& volume) {
  return {volume.width(), volume.height(), volume.channels(), volume.axis()};
}

PixelSpan wholeVolume(const TransientVolume& volume, const TransientVolume* directOnly,
                      const std::vector<const TransientVolume*>* bounces) {
  PixelSpan span{0,
                 static_cast<std::size_t>(volume.width()) * volume.height(),
                 volume.data(),
                 directOnly ? directOnly->data() : nullptr,
                 {}};
  if (bounces) {
    for (const TransientVolume* b : *bounces) span.bounces.push_back(b->data());
  }
  return span;
}

}  // namespace tofsim::sensors
