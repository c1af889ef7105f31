#pragma once
// The GL side of the pixel footprint's difference buffer (render.pixel_footprint,
// core/physics/footprint_kernel.md): per pixel of a segment, bins x 3 doubles
// the gathers deposit wide kernels into (footprint_deposit.glsl) and a flag
// saying it was written; footprint_integrate.comp adds it to a volume as bin
// integrals and leaves it zero for the next gathers.

#include <cstddef>
#include <cstdint>

#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Program.h"

namespace tofsim::render {

class PixelFootprint {
 public:
  /// Room for segments of `pixelsPerSegment` pixels of `bins` bins.
  PixelFootprint(std::size_t pixelsPerSegment, int32_t bins);

  /// Zeroes the buffer and binds the first `pixels` pixels of it for the gathers.
  void beginSegment(std::size_t pixels);
  /// Adds the buffer's bin integrals of the segment's `pixels` pixels to
  /// `volume` (pixels x bins x 3 floats) and zeroes what it read.
  void integrateInto(const gl::Buffer& volume, std::size_t pixels) const;

 private:
  int32_t bins_;
  gl::Buffer diff_, written_;
  gl::Program integrate_;
};

}  // namespace tofsim::render
