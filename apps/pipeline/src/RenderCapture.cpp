#include "tofsim/pipeline/RenderCapture.h"

#include <cstdio>
#include <optional>
#include <utility>
#include <vector>

#include "Warning.h"
#include "tofsim/optics/PsfConvolution.h"
#include "tofsim/pipeline/AxisReport.h"
#include "tofsim/pipeline/Capture.h"
#include "tofsim/pipeline/FiniteSegments.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/pipeline/PsfSegments.h"
#include "tofsim/pipeline/RendererFactory.h"
#include "tofsim/pipeline/SteadySink.h"
#include "tofsim/pipeline/VignettedSegments.h"

namespace tofsim::pipeline {

namespace {
double sumOf(const Image& image) {
  double sum = 0.0;
  for (float v : image.data) sum += v;
  return sum;
}
}  // namespace

capture::RenderJob prepareCapture(const config::RunConfig& config, const scene::Scene& scene,
                                  bool notes) {
  capture::RenderJob job = makeRenderJob(config, scene);
  checkAxisBeforeRender(config, job, notes);  // a proven cut fails here under --strict
  return job;
}

// The links from the renderer to the consumers, in the order light passes
// them: the vignetting, the non-finite filter, the PSF (with the consumers
// before it beside it), then the consumers and the steady sum.
struct CaptureChain::Links {
  std::optional<SteadySink> steady;
  std::optional<capture::TeeSink> tee;
  std::optional<PsfSegments> psf;
  std::optional<capture::TeeSink> psfAndSharp;
  std::optional<FiniteSegments> finite;
  std::optional<VignettedSegments> vignetted;
};

CaptureChain::CaptureChain(const config::RunConfig& config, const capture::RenderJob& job,
                           const CaptureConsumers& consumers)
    : config_(config), job_(job), psfOnRaws_(consumers.psfOnRaws), links_(new Links) {
  Links& l = *links_;
  const int32_t width = capture::imageWidth(job.imager), height = capture::imageHeight(job.imager);
  const TimeAxis& axis = job.settings.time;
  l.steady.emplace(width, height, axis.bins);
  std::vector<capture::SegmentSink*> sinks = consumers.sinks;
  sinks.push_back(&*l.steady);
  const auto& psfConfig = config.camera.psf;
  const bool psfOnTransient = psfConfig && !consumers.psfOnRaws;
  if (!psfOnTransient)
    sinks.insert(sinks.end(), consumers.beforePsf.begin(), consumers.beforePsf.end());
  l.tee.emplace(std::move(sinks));
  // The lens's PSF on the cleaned light (no NaN to spread), before the
  // outputs read it; it holds the volume, so it is checked against the
  // budget first.
  if (psfOnTransient) {
    checkPsfFits(config, width, height, axis.bins, consumers.bounces.size());
    l.psf.emplace(*l.tee, width, height, axis.bins, psfConfig->kernel, config.cpu_threads);
    std::vector<capture::SegmentSink*> both = consumers.beforePsf;
    both.push_back(&*l.psf);
    l.psfAndSharp.emplace(std::move(both));
  }
  capture::SegmentSink& cleaned =
      l.psfAndSharp ? static_cast<capture::SegmentSink&>(*l.psfAndSharp) : *l.tee;
  l.finite.emplace(cleaned, axis.bins, consumers.bounces);
  // The camera's vignetting, before anything reads the light.
  const capture::Camera* camera = capture::cameraOf(job.imager);
  if (std::vector<float> gains = camera ? capture::vignettingGains(*camera, config.camera.vignetting)
                                        : std::vector<float>{};
      !gains.empty()) {
    l.vignetted.emplace(*l.finite, axis.bins, std::move(gains));
  }
}

CaptureChain::~CaptureChain() = default;

capture::SegmentSink& CaptureChain::first() {
  if (links_->vignetted) return *links_->vignetted;
  return *links_->finite;
}

RenderedCapture CaptureChain::finish(capture::RenderResult result, const RendererChoice& choice) {
  Links& l = *links_;
  RenderedCapture rendered;
  rendered.backend = choice.backend;
  rendered.device = choice.renderer->description();
  rendered.result = std::move(result);
  rendered.result.nonFiniteRejected = l.finite->nonFiniteValues();
  if (rendered.result.nonFiniteRejected > 0) {
    warn(std::to_string(rendered.result.nonFiniteRejected) +
         " NaN/infinite volume values written as 0 (transient.json "
         "stats.rejected_non_finite_values)");
  }
  rendered.steady = l.steady->steady();
  const auto& psfConfig = config_.camera.psf;
  if (psfConfig && psfOnRaws_) {  // the sum over bins of the blurred bins, by linearity
    Image& s = rendered.steady;
    optics::applyPsf(psfConfig->kernel, s.data.data(), static_cast<std::size_t>(s.channels),
                     {s.width, s.height, static_cast<std::size_t>(s.channels), 1},
                     {optics::PsfMethod::Auto, config_.cpu_threads});
  }
  // The light on the axis in the terms of the light the renderer counted off
  // it: before the vignetting's gains (with a gain after it on the axis and
  // before it off it, an all-zero map made all the light "late").
  rendered.result.onAxisEnergy =
      l.vignetted ? l.vignetted->lightBeforeGain() : sumOf(rendered.steady);
  checkAxisAfterRender(config_, job_, rendered.result);  // throws under --strict
  return rendered;
}

RenderedCapture renderCapture(const config::RunConfig& config, const capture::RenderJob& job,
                              gl::EglPlatform eglPlatform, const CaptureConsumers& consumers,
                              Progress& progress) {
  PreparedRenderer prepared(eglPlatform);
  std::optional<RenderedCapture> rendered;
  CaptureLoopOptions loop;
  loop.withinCapture = [&](std::size_t done, std::size_t total, const std::string& what) {
    progress.update(done, total, what);
  };
  renderCaptures(
      prepared, config, 1, [&](std::size_t) { return job; },
      [&](std::size_t, const capture::RenderJob& j) {
        return std::make_unique<ConsumersSink>(config, j, consumers, rendered);
      },
      loop);
  progress.message("device: " + rendered->device + " (backend " + rendered->backend + ")");
  return std::move(*rendered);
}

}  // namespace tofsim::pipeline
