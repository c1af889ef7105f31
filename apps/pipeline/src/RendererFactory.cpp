#include "tofsim/pipeline/RendererFactory.h"

#include "tofsim/ir/IrRenderer.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/render/GlBackend.h"

namespace tofsim::pipeline {

std::unique_ptr<ir::IrBackend> makeIrBackend(const config::RunConfig& /*config*/,
                                             gl::EglPlatform eglPlatform) {
  return std::make_unique<render::GlBackend>(std::make_unique<gl::Context>(eglPlatform));
}

std::unique_ptr<capture::Renderer> makeRenderer(const config::RunConfig& config,
                                                gl::EglPlatform eglPlatform) {
  if (config.renderer == config::RendererKind::Reference) {
    reference::ReferenceSettings settings;
    settings.bounces = config.reference.bounces;
    settings.samples_per_pixel = config.reference.samples_per_pixel;
    settings.threads = config.reference.threads;
    settings.pixel_filter = config.reference.pixel_filter == config::ReferencePixelFilter::Box
                                ? reference::PixelFilter::Box
                                : reference::PixelFilter::Point;
    return std::make_unique<reference::ReferenceRenderer>(settings);
  }
  return std::make_unique<ir::IrRenderer>(makeIrBackend(config, eglPlatform));
}

}  // namespace tofsim::pipeline
