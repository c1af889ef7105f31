#pragma once
// The GL backend's per-region media (issue 42's `media:`): the regions'
// triangles and media on the device (shaders/medium_regions.glsl), and every
// G-buffer sample's camera and light legs through them, found once per render
// by shaders/region_legs.comp for the gathers (region_sample_legs.glsl). The
// indirect gather finds each VPL -> sample leg itself from the same buffers.
// Made only for a job with media: without them the GL backend runs what it
// ran before. The physics: core/physics/medium_attenuation.md.

#include <cstddef>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Program.h"

namespace tofsim::render {

class RegionLegs {
 public:
  /// The regions of `job` (its settings' media joined by name with its
  /// scene's region meshes); foldModel as the gathers' (gpu::gatherDefines).
  /// Throws InputError where the regions have more triangles than
  /// glRegionTriangleLimit allows at the job's pixel samples.
  RegionLegs(const capture::RenderJob& job, bool foldModel);

  /// Finds every sample's legs, with the G-buffer's surfaces bound as for
  /// the gathers; throws where a pass came near llvmpipe's loop-trip limit or
  /// a leg crossed a region's surface more often than the shaders keep.
  void compute() const;
  /// Binds the regions, their triangles and the samples' legs.
  void bind() const;
  /// Sets a gather's uRegionCount (the indirect gather walks the regions).
  void setUniforms(const gl::Program& program) const;
  /// The regions' triangles in all (the indirect gather's loop trips).
  std::size_t triangles() const { return triangles_; }
  std::size_t regions() const { return regions_; }
  /// Device memory held: the regions, their triangles, two vec4 per sample.
  std::size_t bytes() const { return regionBuffer_.size() + corners_.size() + legs_.size(); }

 private:
  std::size_t regions_ = 0, triangles_ = 0, records_ = 0;
  gl::Program program_;
  gl::Buffer regionBuffer_, corners_, legs_, guard_;
};

}  // namespace tofsim::render
