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
#include <string>
#include <vector>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/gl/Context.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/RendererFactory.h"
#include "tofsim/scene/Scene.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::pipeline {

/// The render job of `config` over `scene` (Capture.h), its time axis checked
/// before rendering: a proven cut warns, or under render.strict throws.
capture::RenderJob prepareCapture(const config::RunConfig& config, const scene::Scene& scene);

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

/// Renders `job` with the configured renderer into `consumers` (progress on
/// `progress`, which also names the device), warns of values written as 0
/// (even when quiet: the outputs differ from what the renderer produced),
/// then checks the light lost off the time axis (throws InputError under
/// render.strict; the consumers have then had every segment, and the caller
/// commits nothing).
RenderedCapture renderCapture(const config::RunConfig& config, const capture::RenderJob& job,
                              gl::EglPlatform eglPlatform, const CaptureConsumers& consumers,
                              Progress& progress);
/// The same with a renderer made earlier (makeRenderer), kept across the
/// renders of a sequence so that its device and scene are set up once (the
/// caller names the device: not once per render).
RenderedCapture renderCapture(const config::RunConfig& config, const capture::RenderJob& job,
                              const RendererChoice& renderer, const CaptureConsumers& consumers,
                              Progress& progress);

}  // namespace tofsim::pipeline
