#pragma once
// The one loop over captures (issue 40 item 4): captures -- each a
// {scene time, light, imager} job -- rendered through one prepared renderer
// into the sinks their caller makes. NLOS scans (a laser spot per capture),
// sequences (a frame per capture) and single renders (one capture) go
// through it, as will a scanning lidar's beams. The loop knows no capture
// kind: the imager is in the job, and what the light becomes is the sink's.
//
// For each capture i: jobOf(i) (which may move the scene to its time), then
// sinkOf(i, job), the render into the sink's segments, then the sink's
// finish(). A signal (SIGINT/SIGTERM, util/Interrupt.h) stops the loop
// before the next capture and after each render: the capture in flight is
// never finished, its sink is destroyed unfinished (what it staged goes with
// it), and Interrupted propagates. So does any error, the same way.

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/RendererFactory.h"

namespace tofsim::pipeline {

class PreparedRenderer;

/// Where one capture's light goes.
class CaptureSink {
 public:
  virtual ~CaptureSink() = default;
  /// The stream the renderer writes the capture's segments into.
  virtual capture::SegmentSink& segments() = 0;
  /// After the capture rendered whole, by `renderer`: what the sink does with
  /// the light (keeps it, writes and commits its files). Never called for a
  /// capture that was interrupted or failed.
  virtual void finish(const capture::RenderResult& result, const RendererChoice& renderer) = 0;
};

/// Capture i's job. With workers > 1, called concurrently for different i.
using CaptureJobOf = std::function<capture::RenderJob(std::size_t i)>;
/// Capture i's sink, made after its job (which it may keep a reference to:
/// the job lives until the sink is destroyed). Concurrent as jobOf.
using CaptureSinkOf =
    std::function<std::unique_ptr<CaptureSink>(std::size_t i, const capture::RenderJob& job)>;

struct CaptureLoopOptions {
  /// Captures rendered at once, each on a renderer of its own: the prepared
  /// one, and for the others fresh ones like it, kept for the loop (each
  /// prepares the scene once). 1: in order, on the prepared renderer. Only
  /// for renderers that may run on several threads (not GL: its context is
  /// current on one); the bytes must not depend on it (each capture has its
  /// own sink, and renderers' bytes do not depend on their threads).
  int workers = 1;
  /// After each finished capture: (captures finished, count, unit).
  capture::ProgressCallback captureDone;
  std::string unit = "captures";
  /// The renderer's own progress within a capture (workers == 1 only).
  capture::ProgressCallback withinCapture;
};

struct CaptureLoopStats {
  std::size_t captures = 0;           ///< finished
  std::size_t vpls = 0;               ///< summed over the captures
  std::size_t scenePreparations = 0;  ///< by the loop's renderers, during the loop
  std::size_t renderers = 0;          ///< that rendered: at most `workers`
  std::string backend;                ///< RendererChoice::backend
  std::string device;                 ///< the renderer's description
};

/// Renders captures 0 .. count-1 (see the top) with prepared.renderer(
/// rendererConfig): the renderer rendererConfig's render.* asks for, made
/// there or kept from earlier renders.
CaptureLoopStats renderCaptures(PreparedRenderer& prepared, const config::RunConfig& rendererConfig,
                                std::size_t count, const CaptureJobOf& jobOf,
                                const CaptureSinkOf& sinkOf,
                                const CaptureLoopOptions& options = {});

}  // namespace tofsim::pipeline
