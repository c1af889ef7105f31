#pragma once
// Transient instant radiosity on OpenGL 4.5 (Pan, Arellano, Jarabo 2019): the
// backend-independent driver (ir::IrRenderer) over the GL backend
// (render::GlBackend) on a given context.
//
// The volume is produced in segments sized by the memory budget and the GL
// implementation's limits and handed to a SegmentSink as soon as each is done.

#include "tofsim/ir/IrRenderer.h"

namespace tofsim::gl {
class Context;
}

namespace tofsim::render {

using capture::ProgressCallback;
using capture::RenderJob;
using capture::RenderResult;
using capture::SegmentSink;

class TransientRenderer : public ir::IrRenderer {
 public:
  /// `context` must outlive the renderer.
  explicit TransientRenderer(gl::Context& context);
};

}  // namespace tofsim::render
