#pragma once
// Renders a non-line-of-sight scan: each laser position is one capture of the
// scene, prepared once per renderer; the light that left the wall at the
// laser spot and came back to a sensor point (the indirect light: the laser
// spot's own direct return is not in H, as in y-tal) is summed over R, G and
// B into that point's histogram of H.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/gl/Context.h"
#include "tofsim/pipeline/NlosScan.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::pipeline {

class PreparedRenderer;

struct NlosVolume {
  TimeAxis axis;
  std::vector<std::size_t> shape;  ///< {T, sx, sy} or {T, lx, ly, sx, sy}
  std::vector<float> H;            ///< row-major in `shape`: time slowest, as y-tal holds it
  std::size_t captures = 0;
  std::size_t scenePreparations = 0;  ///< one per renderer that ran
  std::size_t vpls = 0;               ///< summed over the captures
  double seconds = 0.0;
  std::string device;
  std::string backend;  ///< "cpu" or "gl" (render.backend, auto decided), or "reference"
};

/// The seed capture `capture` (its index in the scan, NlosScanGeometry's
/// order) renders with under render.renderer: reference, from render.seed:
/// each laser position draws its own paths, the same whatever the thread
/// count or the order the captures run in. (IR's captures all use render.seed.)
uint64_t nlosCaptureSeed(uint64_t seed, std::size_t capture);

/// Renders the scan's captures through the capture loop (CaptureLoop.h) with
/// `prepared`'s renderer: IR over render.backend (the CPU one with
/// render.cpu_threads, or GL), or the reference path tracer (render.renderer:
/// reference, render.reference.*, its threads from render.reference.threads).
/// On the CPU, scans of few points per capture (confocal) run their captures
/// in parallel, one single-threaded renderer per worker; the others (and
/// every GL scan, on its one context) one capture after another. The bytes
/// are the same either way (neither renderer's depend on its thread count).
NlosVolume renderNlosScan(const config::RunConfig& config, const scene::Scene& scene,
                          const NlosScanGeometry& scan, PreparedRenderer& prepared,
                          const capture::ProgressCallback& progress = {});
/// The same with a renderer made for this scan (on an EGL context of
/// `eglPlatform` for GL).
NlosVolume renderNlosScan(const config::RunConfig& config, const scene::Scene& scene,
                          const NlosScanGeometry& scan,
                          const capture::ProgressCallback& progress = {},
                          gl::EglPlatform eglPlatform = gl::EglPlatform::Auto);

}  // namespace tofsim::pipeline
