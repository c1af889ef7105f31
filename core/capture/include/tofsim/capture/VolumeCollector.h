#pragma once
// A SegmentSink that keeps the whole volume in memory (tests, small renders).

#include "tofsim/capture/SegmentSink.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::capture {

class VolumeCollector : public SegmentSink {
 public:
  /// bounces N >= 1: also keep bounce1 .. bounceN (the segments must carry
  /// them: an IR render with render.indirect.bounces N > 1).
  VolumeCollector(int32_t width, int32_t height, const TimeAxis& axis, int32_t channels,
                  int32_t bounces = 0);
  void consume(const Segment& segment) override;
  TransientVolume direct;
  TransientVolume indirect;
  std::vector<TransientVolume> bounces;  ///< bounce1 .. bounceN, when asked
  /// direct + indirect, computed in float: total == direct + indirect exactly.
  TransientVolume total() const;
};

/// "R", "G", "B" for three channels, "C0", "C1", ... otherwise.
std::vector<std::string> defaultChannelNames(int32_t channels);

}  // namespace tofsim::capture
