#pragma once
// A SegmentSink that keeps the whole volume in memory (tests, small renders).

#include "tofsim/capture/SegmentSink.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::capture {

class VolumeCollector : public SegmentSink {
 public:
  VolumeCollector(int32_t width, int32_t height, const TimeAxis& axis, int32_t channels);
  void consume(const Segment& segment) override;
  TransientVolume direct;
  TransientVolume indirect;
  /// direct + indirect, computed in float: total == direct + indirect exactly.
  TransientVolume total() const;
};

/// "R", "G", "B" for three channels, "C0", "C1", ... otherwise.
std::vector<std::string> defaultChannelNames(int32_t channels);

}  // namespace tofsim::capture
