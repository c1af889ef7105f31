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

reference::ReferenceSettings makeReferenceSettings(const config::ReferenceConfig& config) {
  reference::ReferenceSettings settings;
  settings.bounces = config.bounces;
  settings.samples_per_pixel = config.samples_per_pixel;
  settings.threads = config.threads;
  settings.pixel_filter = config.pixel_filter == config::ReferencePixelFilter::Box
                              ? reference::PixelFilter::Box
                              : reference::PixelFilter::Point;
  settings.sampling = config.sampling == config::ReferenceSampling::Brdf
                          ? reference::ContinuationSampling::BrdfMixture
                          : reference::ContinuationSampling::Cosine;
  return settings;
}

bool RendererSpec::operator==(const RendererSpec& o) const {
  if (kind != o.kind) return false;
  if (kind == config::RendererKind::Reference) return reference == o.reference;
  return backend == o.backend && cpuThreads == o.cpuThreads;
}

RendererSpec rendererSpec(const config::RunConfig& config,
                          std::optional<config::IrBackendKind> autoBackend) {
  RendererSpec spec;
  spec.kind = config.renderer;
  spec.reference = config.reference;
  spec.cpuThreads = config.cpu_threads;
  if (config.renderer == config::RendererKind::Reference) return spec;
  // What the GL backend does not gather, auto gives to the CPU backend.
  const capture::IrCapabilities need =
      capture::irNeeds(config.nlos ? nullptr : &config.camera.camera, config.render);
  if (config.backend != config::IrBackendKind::Auto) {
    spec.backend = config.backend;
  } else if (!capture::covers(capture::kGlCapabilities, need)) {
    spec.backend = config::IrBackendKind::Cpu;
  } else {
    spec.backend = autoBackend ? *autoBackend : resolveIrBackend(config.backend);
  }
  return spec;
}

RendererChoice makeRenderer(const RendererSpec& spec, gl::EglPlatform eglPlatform) {
  if (spec.kind == config::RendererKind::Reference) {
    return {std::make_unique<reference::ReferenceRenderer>(makeReferenceSettings(spec.reference)),
            "reference"};
  }
  return {std::make_unique<ir::IrRenderer>(makeIrBackend(spec.backend, eglPlatform, spec.cpuThreads)),
          config::irBackendName(spec.backend)};
}

RendererChoice makeRenderer(const config::RunConfig& config, gl::EglPlatform eglPlatform) {
  return makeRenderer(rendererSpec(config), eglPlatform);
}

}  // namespace tofsim::pipeline
