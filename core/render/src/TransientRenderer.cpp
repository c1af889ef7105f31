#include "tofsim/render/TransientRenderer.h"

#include <memory>

#include "tofsim/render/GlBackend.h"

namespace tofsim::render {

TransientRenderer::TransientRenderer(gl::Context& context)
    : ir::IrRenderer(std::make_unique<GlBackend>(context)) {}

}  // namespace tofsim::render
