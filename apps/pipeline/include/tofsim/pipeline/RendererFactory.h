#pragma once
// The one place that turns a config's renderer choice into a capture::Renderer.
// IR renderers are the backend-independent driver over an ir::IrBackend
// (makeIrBackend): render.backend picks the GL backend (core/render, on an EGL
// context) or the CPU one (core/cpu, no EGL at all).

#include <memory>
#include <optional>
#include <string>

#include "tofsim/capture/Renderer.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/gl/Context.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/reference/ReferenceRenderer.h"

namespace tofsim::pipeline {

/// render.backend with `auto` decided: gl when the EGL device platform offers
/// a hardware GPU (gl::hardwareGpuName), cpu otherwise (llvmpipe is several
/// times slower than the CPU backend on the same cores).
config::IrBackendKind resolveIrBackend(config::IrBackendKind requested);

/// The IR backend `backend` names (not Auto): GL on a new EGL context of
/// `eglPlatform`, or the CPU backend on `cpuThreads` threads (0: every core).
std::unique_ptr<ir::IrBackend> makeIrBackend(config::IrBackendKind backend,
                                             gl::EglPlatform eglPlatform, int cpuThreads = 0);

/// The reference path tracer's settings from render.reference.*.
reference::ReferenceSettings makeReferenceSettings(const config::ReferenceConfig& config);

/// What renders a run, for the log and transient.json.
struct RendererChoice {
  std::unique_ptr<capture::Renderer> renderer;
  std::string backend;  ///< "gl" or "cpu" for IR, "reference" for the path tracer
};

/// What a renderer is made from: configs with equal specs get renderers that
/// render alike, so one made for the first serves the others
/// (PreparedRenderer keeps it).
struct RendererSpec {
  config::RendererKind kind = config::RendererKind::InstantRadiosity;
  /// IR: render.backend decided (never Auto); a defocused camera or merged
  /// pixel samples under auto take the CPU backend, the one that does them.
  config::IrBackendKind backend = config::IrBackendKind::Cpu;
  int cpuThreads = 0;                 ///< IR: render.threads
  config::ReferenceConfig reference;  ///< reference: render.reference.*
  bool operator==(const RendererSpec& other) const;
};

/// The spec of `config`'s renderer; `autoBackend`: what render.backend: auto
/// resolves to (resolveIrBackend(Auto), which asks EGL, when not given).
RendererSpec rendererSpec(const config::RunConfig& config,
                          std::optional<config::IrBackendKind> autoBackend = std::nullopt);

/// render.renderer: ir -> ir::IrRenderer over makeIrBackend(spec.backend);
/// reference -> the CPU path tracer with render.reference.* (needs no GL
/// context).
RendererChoice makeRenderer(const RendererSpec& spec, gl::EglPlatform eglPlatform);
/// makeRenderer(rendererSpec(config), eglPlatform).
RendererChoice makeRenderer(const config::RunConfig& config, gl::EglPlatform eglPlatform);

}  // namespace tofsim::pipeline
