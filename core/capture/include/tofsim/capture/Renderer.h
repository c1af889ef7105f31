#pragma once
// What every renderer offers the pipeline: render a job into a segment stream.
// Implemented by the IR driver (ir::IrRenderer, over any ir::IrBackend) and by
// the CPU reference path tracer; the pipeline picks one by configuration and
// never branches on the kind again.

#include <string>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/capture/SegmentSink.h"

namespace tofsim::capture {

class Renderer {
 public:
  virtual ~Renderer() = default;
  /// The device it runs on, for logs and transient.json, e.g. "llvmpipe
  /// (LLVM 15.0.6, 256 bits)" or "CPU reference path tracer".
  virtual std::string description() const = 0;
  /// Streams the job's volume to `sink` in order (see SegmentSink.h) and
  /// returns the depth and statistics. Throws InputError for settings the
  /// renderer or its device cannot honour.
  virtual RenderResult render(const RenderJob& job, SegmentSink& sink,
                              const ProgressCallback& progress = {}) const = 0;
  /// The scene of the last render was changed in place (an animation's next
  /// frame, scene::AnimatedScene::updateScene): the next render prepares it
  /// again. Renderers that keep nothing of a scene ignore it.
  virtual void sceneChanged() const {}
};

}  // namespace tofsim::capture
