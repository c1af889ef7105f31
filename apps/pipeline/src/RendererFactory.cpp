#include "tofsim/pipeline/RendererFactory.h"

#include "tofsim/capture/IrCapabilities.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/render/GlBackend.h"

namespace tofsim::pipeline {

config::IrBackendKind resolveIrBackend(config::IrBackendKind requested) {
  if (requested != config::IrBackendKind::Auto) return requested;
  return gl::hardwareGpuName() ? config::IrBackendKind::Gl : config::IrBackendKind::Cpu;
}

std::unique_ptr<ir::IrBackend> makeIrBackend(config::IrBackendKind backend,
                                             gl::EglPlatform eglPlatform, int cpuThreads) {
  if (backend == config::IrBackendKind::Cpu) {
    cpu::CpuBackendOptions options;
    options.threads = cpuThreads;
    return std::make_unique<cpu::CpuBackend>(options);
  }
  return std::make_unique<render::GlBackend>(std::make_unique<gl::Context>(eglPlatform));
}

reference::ReferenceSettings makeReferenceSettings(const config::RunConfig& config) {
  reference::ReferenceSettings settings;
  settings.bounces = config.reference.bounces;
  settings.samples_per_pixel = config.reference.samples_per_pixel;
  settings.threads = config.reference.threads;
  settings.pixel_filter = config.reference.pixel_filter == config::ReferencePixelFilter::Box
                              ? reference::PixelFilter::Box
                              : reference::PixelFilter::Point;
  settings.sampling = config.reference.sampling == config::ReferenceSampling::Brdf
                          ? reference::ContinuationSampling::BrdfMixture
                          : reference::ContinuationSampling::Cosine;
  return settings;
}

RendererChoice makeRenderer(const config::RunConfig& config, gl::EglPlatform eglPlatform) {
  if (config.renderer == config::RendererKind::Reference) {
    return {std::make_unique<reference::ReferenceRenderer>(makeReferenceSettings(config)),
            "reference"};
  }
  // What the GL backend does not gather, auto gives to the CPU backend.
  const capture::IrCapabilities need =
      capture::irNeeds(config.nlos ? nullptr : &config.camera.camera, config.render);
  const config::IrBackendKind backend = !capture::covers(capture::kGlCapabilities, need) &&
                                                config.backend == config::IrBackendKind::Auto
                                            ? config::IrBackendKind::Cpu
                                            : resolveIrBackend(config.backend);
  return {std::make_unique<ir::IrRenderer>(makeIrBackend(backend, eglPlatform, config.cpu_threads)),
          config::irBackendName(backend)};
}

}  // namespace tofsim::pipeline
