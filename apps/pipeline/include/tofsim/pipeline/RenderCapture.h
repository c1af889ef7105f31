#pragma once
// One way through a render, for the CLI's run (RenderRun.h) and the Python
// module's in-memory render alike: the job from the config with the time
// axis checked before rendering, then the configured renderer's segments
// made finite (FiniteSegments.h), through the lens's PSF (PsfSegments.h,
// unless the consumers apply it: CaptureConsumers::psfOnRaws) and fed to
// the caller's consumers, the
// steady image summed, and the light off the time axis measured and checked
// (AxisReport.h: a warning, or under render.strict an error).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/gl/Context.h"
#include "tofsim/pipeline/CaptureLoop.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/RendererFactory.h"
#include "tofsim/scene/Scene.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::pipeline {

/// The render job of `config` over `scene` (Capture.h), its time axis checked
/// before rendering: a proven cut warns, or under render.strict throws;
/// `notes` (validate) also prints a possible cut as a note.
capture::RenderJob prepareCapture(const config::RunConfig& config, const scene::Scene& scene,
                                  bool notes = false);

/// Who takes the cleaned segments: each gets every segment in order, with
/// the components direct, indirect, total (kTotal) and the bounces listed
/// (capture::bounceComponent's k).
struct CaptureConsumers {
  std::vector<capture::SegmentSink*> sinks;
  std::vector<int32_t> bounces;
  /// Consumers of the light before the lens's PSF (camera.psf), given each
  /// segment as it comes: a sensor that applies the PSF on its own images
  /// (optics::applyPsf on CW-ToF's raws, far cheaper than on every bin).
  /// Without a PSF they see what `sinks` see.
  std::vector<capture::SegmentSink*> beforePsf;
  /// The PSF is left to the consumers (PsfPath::Raws: the CW-ToF sensors
  /// apply it on their raws, StreamOptions::psfOnRaws): every consumer gets
  /// the light before it, and renderCapture convolves only the steady image.
  bool psfOnRaws = false;
};

struct RenderedCapture {
  /// nonFiniteRejected and onAxisEnergy filled in.
  capture::RenderResult result;
  std::string backend;  ///< RendererChoice::backend
  std::string device;   ///< the renderer's description
  Image steady;         ///< the total summed over time (through the lens's PSF)
};

/// renderCapture's way from the renderer to the consumers, for a caller that
/// runs the render itself (a capture loop's sink, CaptureLoop.h): made
/// before the render (a PSF that does not fit fails here), first() handed to
/// the renderer, finish() after a complete render.
class CaptureChain {
 public:
  CaptureChain(const config::RunConfig& config, const capture::RenderJob& job,
               const CaptureConsumers& consumers);
  ~CaptureChain();
  CaptureChain(const CaptureChain&) = delete;
  CaptureChain& operator=(const CaptureChain&) = delete;
  /// Where the renderer writes the segments.
  capture::SegmentSink& first();
  /// After the render that gave `result` (by `renderer`): renderCapture's
  /// warnings, steady image and axis check (throws under render.strict).
  RenderedCapture finish(capture::RenderResult result, const RendererChoice& renderer);

 private:
  struct Links;
  const config::RunConfig& config_;
  const capture::RenderJob& job_;
  bool psfOnRaws_;
  std::unique_ptr<Links> links_;
};

/// A capture loop's sink (CaptureLoop.h) through a CaptureChain to
/// `consumers`: what the chain's finish() gives goes to `rendered`.
class ConsumersSink : public CaptureSink {
 public:
  ConsumersSink(const config::RunConfig& config, const capture::RenderJob& job,
                const CaptureConsumers& consumers, std::optional<RenderedCapture>& rendered)
      : chain_(config, job, consumers), rendered_(rendered) {}
  capture::SegmentSink& segments() override { return chain_.first(); }
  void finish(const capture::RenderResult& result, const RendererChoice& renderer) override {
    rendered_ = chain_.finish(result, renderer);
  }

 private:
  CaptureChain chain_;
  std::optional<RenderedCapture>& rendered_;
};

/// Renders `job` with a renderer made for it (render.renderer, render.backend
/// on an EGL context of `eglPlatform`) into `consumers`, one capture through
/// the capture loop: progress on `progress`, which also names the device;
/// warns of values written as 0 (even when quiet: the outputs differ from
/// what the renderer produced), then checks the light lost off the time axis
/// (throws InputError under render.strict; the consumers have then had every
/// segment, and the caller commits nothing).
RenderedCapture renderCapture(const config::RunConfig& config, const capture::RenderJob& job,
                              gl::EglPlatform eglPlatform, const CaptureConsumers& consumers,
                              Progress& progress);

}  // namespace tofsim::pipeline
