#pragma once
// The GL side of the pixel footprint's difference buffer (render.pixel_footprint,
// core/physics/footprint_kernel.md): per pixel of a segment, bins x 3 doubles
// the gathers deposit wide kernels into (footprint_deposit.glsl) and a flag
// saying it was written; footprint_integrate.comp adds it to a volume as bin
// integrals and leaves it zero for the next gathers.
//
// With delayed response classes (core/physics/temporal_response.md) the
// buffer holds one more region of the same size per class (class c's at
// region c, footprint_deposit.glsl's depositDelayed), one more as scratch
// where a class is a cascade of several kernels, and integrateInto runs the
// temporal-response stage after the instant class: response_integrate.comp
// per class and member, which also books the light past the axis in the
// buffer bound at TOFSIM_SSBO_OUTSIDE_AXIS. Without classes nothing of it is
// allocated or run.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Program.h"
#include "tofsim/physics/TemporalResponse.h"

namespace tofsim::render {

class PixelFootprint {
 public:
  /// Room for segments of `pixelsPerSegment` pixels of `bins` bins; class c
  /// >= 1 filtered by the cascade delayed[c - 1] (physics::classStages).
  PixelFootprint(std::size_t pixelsPerSegment, int32_t bins,
                 const std::vector<std::vector<physics::ResponseTaps>>& delayed = {});

  /// Zeroes the buffer and binds the first `pixels` pixels of it for the
  /// gathers (every class's region with delayed classes).
  void beginSegment(std::size_t pixels);
  /// Adds the buffer's bin integrals of the segment's `pixels` pixels to
  /// `volume` (pixels x bins x 3 floats), then each delayed class's light
  /// through its kernel, and zeroes what it read.
  void integrateInto(const gl::Buffer& volume, std::size_t pixels);
  /// Pixels per region (footprint_deposit.glsl's uResponseRegionPixels).
  std::size_t regionPixels() const { return regionPixels_; }

 private:
  struct StageTaps;
  void integrateClasses(std::size_t pixels);
  void integrateStage(const StageTaps& t, std::size_t pixels);

  int32_t bins_;
  std::size_t regionPixels_;
  std::size_t classes_;  ///< delayed classes
  std::size_t regions_;  ///< of the buffer: the instant one, the classes', a scratch
  gl::Buffer diff_, written_;
  gl::Program integrate_;
  // With delayed classes only.
  struct StageTaps {
    uint32_t offset = 0;  ///< into taps_: prompt, ratio, weight, matrix, taps
    int32_t delay = 0;
    int32_t count = 0;
    bool reemits = false;
  };
  std::vector<std::vector<StageTaps>> classTaps_;  ///< [class - 1][member]
  gl::Buffer taps_, state_;
  gl::Program response_;
};

}  // namespace tofsim::render
