#pragma once
// The GL backend's VPL light scattered by the medium into the camera rays
// (issue 42, item 4): shaders/medium_vpls.comp, VPL by VPL, after each batch's
// indirect gather, into a volume and off-axis sums of its own, which the
// read-backs add to the indirect light (so that each bin sums its VPLs in
// index order whatever the batch plan, as the CPU backend does). Made only
// for a render with VPLs and a scattering medium (capture::Medium::scatters). The
// physics: core/physics/medium_vpl_scattering.md.

#include <cstddef>
#include <vector>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Program.h"
#include "tofsim/ir/IrBackend.h"

namespace tofsim::render {

class IndirectLight;
class MediumDirect;

class MediumVpls {
 public:
  /// For `job` and its `vpls` (the pairs' roulette threshold); `direct`
  /// holds the samples' rays.
  MediumVpls(const capture::RenderJob& job, const std::vector<ir::Vpl>& vpls,
             const MediumDirect& direct);

  /// Zeroes the volume and sums of a segment of `pixels` pixels (made or
  /// grown here: the plan counted them, ir::MemoryPlan's otherBytes).
  void beginSegment(std::size_t pixels);
  /// VPLs [firstVpl, + count) of `vpls` (their visibility built last) into
  /// the segment's pixels [firstPixel, + pixels), the surfaces bound.
  void gather(const IndirectLight& vpls, std::size_t firstVpl, std::size_t count,
              std::size_t firstPixel, std::size_t pixels) const;
  /// Adds the segment's light to `indirect` (pixels x bins x channels, read
  /// back) and zeroes it; with `outside` (2 floats a pixel) the off-axis sums too.
  void addInto(float* indirect, float* outside, std::size_t pixels);

 private:
  gl::Program program_;
  const MediumDirect& direct_;
  gl::Buffer volume_, outside_;
  std::size_t floatsPerPixel_ = 0;
};

}  // namespace tofsim::render
