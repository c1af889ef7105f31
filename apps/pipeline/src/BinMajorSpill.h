#pragma once
// Private to the render run: the total volume turned bin-major in a temporary
// file, for the outputs that need one time bin of every pixel (the video, the
// frame EXRs and PNGs) while the renderer produces runs of pixels. The run
// then holds one segment and one frame's bins, not the volume.

#include <filesystem>
#include <vector>

#include "tofsim/imaging/Video.h"
#include "tofsim/imaging/WhiteLevel.h"
#include "tofsim/sensors/SensorStream.h"

namespace tofsim::pipeline {

class BinMajorSpill {
 public:
  /// Creates `path` (H W bins C floats once full, bin by bin); the destructor
  /// removes it, whether the run succeeded or not. Throws InputError naming
  /// the file when it cannot be created.
  BinMajorSpill(std::filesystem::path path, const sensors::VolumeShape& shape);
  ~BinMajorSpill();
  BinMajorSpill(const BinMajorSpill&) = delete;
  BinMajorSpill& operator=(const BinMajorSpill&) = delete;

  /// The next run of pixels of the total volume (pixel-major, as rendered).
  void append(const sensors::PixelSpan& span);
  /// The volume bin by bin, from the file; after the last span, valid while
  /// this spill lives.
  imaging::BinFrames frames();
  /// One bin of every pixel ((y, x, c) order) into out.
  void readBin(int32_t t, float* out) const;

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  sensors::VolumeShape shape_;
  imaging::WhiteLevelSampler white_;
  std::vector<float> gather_;
  std::size_t appended_ = 0;  ///< pixels
};

}  // namespace tofsim::pipeline
