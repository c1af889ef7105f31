#pragma once
// The one place that turns a config's renderer choice into a capture::Renderer.
// IR renderers are the backend-independent driver over an ir::IrBackend
// (makeIrBackend), so another backend (render.backend: cpu) is one more case
// there.

#include <memory>

#include "tofsim/capture/Renderer.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/gl/Context.h"
#include "tofsim/ir/IrBackend.h"

namespace tofsim::pipeline {

/// The IR backend the config asks for (today: GL, on a new EGL context).
std::unique_ptr<ir::IrBackend> makeIrBackend(const config::RunConfig& config,
                                             gl::EglPlatform eglPlatform);

/// render.renderer: ir -> ir::IrRenderer over makeIrBackend; reference -> the
/// CPU path tracer with render.reference.* (needs no GL context).
std::unique_ptr<capture::Renderer> makeRenderer(const config::RunConfig& config,
                                                gl::EglPlatform eglPlatform);

}  // namespace tofsim::pipeline
