#include "tofsim/sensors/SensorStream.h"

#include "tofsim/util/Error.h"

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

void appendExposureSamples(double start_s, double exposure_s, int32_t S,
                           std::vector<double>& times) {
  TOFSIM_CHECK(S >= 1);
  for (int32_t m = 0; m < S; ++m) times.push_back(start_s + (m + 0.5) / S * exposure_s);
}

}  // namespace tofsim::sensors
