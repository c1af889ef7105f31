#pragma once
// Transient instant radiosity on OpenGL 4.5 (Pan, Arellano, Jarabo 2019):
// the camera's G-buffer, the light's shadow map and, for indirect light, VPLs
// from a reflective shadow map with imperfect-shadow-map visibility. Every
// contribution lands in the time bin of its full optical path.
//
// The volume is produced in segments sized by the memory budget and the GL
// implementation's limits and handed to a SegmentSink as soon as each is done.

#include "tofsim/capture/RenderJob.h"
#include "tofsim/capture/SegmentSink.h"

namespace tofsim::gl {
class Context;
}

namespace tofsim::render {

using capture::ProgressCallback;
using capture::RenderJob;
using capture::RenderResult;
using capture::SegmentSink;

class TransientRenderer {
 public:
  explicit TransientRenderer(gl::Context& context);
  RenderResult render(const RenderJob& job, SegmentSink& sink,
                      const ProgressCallback& progress = {}) const;

 private:
  gl::Context& context_;
};

}  // namespace tofsim::render
