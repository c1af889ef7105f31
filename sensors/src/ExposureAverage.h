#pragma once
// The mean of a frame's light over an exposure in a moving scene: each pass
// (SensorStream::beginPass) adds its spans, weighted by the number of the
// exposure's samples it stands for, and the mean comes back as one span of
// the whole image in the volume's layout, for a sensor to draw once, as if
// the scene had held still at that light. Sums are in double and divided
// once at the end, so S passes of the same light give that light's floats
// exactly (a still scene: the static capture's bytes). It holds the frame's
// volume: an exposure that moves costs the memory of one.

#include <cstddef>
#include <vector>

#include "tofsim/sensors/SensorStream.h"

namespace tofsim::sensors::detail {

class ExposureAverage {
 public:
  /// `samples`: the exposure's samples S, each pass standing for some of them.
  ExposureAverage(const VolumeShape& shape, std::size_t samples);

  /// The spans until the next beginPass stand for `count` of the samples.
  void beginPass(std::size_t count);
  void add(const PixelSpan& span);
  /// Every sample seen (a pass covering the image for each): the mean as one span.
  PixelSpan mean();

 private:
  VolumeShape shape_;
  std::size_t samples_ = 0, seen_ = 0, weight_ = 0, next_ = 0;
  std::vector<double> sum_;
  std::vector<float> mean_;
};

}  // namespace tofsim::sensors::detail
