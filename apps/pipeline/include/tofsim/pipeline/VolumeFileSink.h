#pragma once
// One component of the volume streamed to its .npy ((H, W, T, C) float32) as
// segments arrive. Nothing appears under the file's name until commit(); an
// exception before then leaves only a removed temporary.

#include <filesystem>
#include <string_view>

#include "tofsim/capture/SegmentSink.h"
#include "tofsim/io/Npy.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::pipeline {

class VolumeFileSink : public capture::SegmentSink {
 public:
  /// component: a name with static lifetime (capture::kDirect, kTotal, ...).
  VolumeFileSink(const std::filesystem::path& file, std::string_view component, int32_t width,
                 int32_t height, const TimeAxis& axis);
  void consume(const capture::Segment& segment) override;
  /// Renames the streamed file into place.
  void commit() { writer_.commit(); }

 private:
  std::string_view component_;
  std::size_t pixelFloats_;
  io::NpyStreamWriter writer_;
};

}  // namespace tofsim::pipeline
