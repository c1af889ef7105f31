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
#include "tofsim/pipeline/PsfSegments.h"
#include "tofsim/pipeline/RendererFactory.h"
#include "tofsim/pipeline/SteadySink.h"
#include "tofsim/pipeline/VignettedSegments.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

namespace {
double sumOf(const Image& image) {
  double sum = 0.0;
  for (float v : image.data) sum += v;
  return sum;
}
}  // namespace

capture::RenderJob prepareCapture(const config::RunConfig& config, const scene::Scene& scene) {
  capture::RenderJob job = makeRenderJob(config, scene);
  checkAxisBeforeRender(config, job, false);  // a proven cut fails here under --strict
  return job;
}

RenderedCapture renderCapture(const config::RunConfig& config, const capture::RenderJob& job,
                              gl::EglPlatform eglPlatform, const CaptureConsumers& consumers,
                              Progress& progress) {
  const RendererChoice choice = makeRenderer(config, eglPlatform);
  RenderedCapture rendered = renderCapture(config, job, choice, consumers, progress);
  progress.message("device: " + rendered.device + " (backend " + rendered.backend + ")");
  return rendered;
}

RenderedCapture renderCapture(const config::RunConfig& config, const capture::RenderJob& job,
                              const RendererChoice& choice, const CaptureConsumers& consumers,
                              Progress& progress) {
  const int32_t width = capture::imageWidth(job.imager), height = capture::imageHeight(job.imager);
  const TimeAxis& axis = job.settings.time;
  SteadySink steady(width, height, axis.bins);
  std::vector<capture::SegmentSink*> sinks = consumers.sinks;
  sinks.push_back(&steady);
  const auto& psfConfig = config.camera.psf;
  const bool psfOnTransient = psfConfig && !consumers.psfOnRaws;
  if (!psfOnTransient)
    sinks.insert(sinks.end(), consumers.beforePsf.begin(), consumers.beforePsf.end());
  capture::TeeSink tee(std::move(sinks));
  // The lens's PSF on the cleaned light (no NaN to spread), before the
  // outputs read it; it holds the volume, so it is checked against the
  // budget first.
  std::optional<PsfSegments> psf;
  std::optional<capture::TeeSink> psfAndSharp;
  if (psfOnTransient) {
    checkPsfFits(config, width, height, axis.bins, consumers.bounces.size());
    psf.emplace(tee, width, height, axis.bins, psfConfig->kernel, config.cpu_threads);
    std::vector<capture::SegmentSink*> both = consumers.beforePsf;
    both.push_back(&*psf);
    psfAndSharp.emplace(std::move(both));
  }
  capture::SegmentSink& cleaned =
      psfAndSharp ? static_cast<capture::SegmentSink&>(*psfAndSharp) : tee;
  FiniteSegments finite(cleaned, axis.bins, consumers.bounces);
  // The camera's vignetting, before anything reads the light.
  std::optional<VignettedSegments> vignetted;
  const capture::Camera* camera = capture::cameraOf(job.imager);
  if (std::vector<float> gains = camera ? capture::vignettingGains(*camera, config.camera.vignetting)
                                        : std::vector<float>{};
      !gains.empty()) {
    vignetted.emplace(finite, axis.bins, std::move(gains));
  }
  capture::SegmentSink& first = vignetted ? static_cast<capture::SegmentSink&>(*vignetted) : finite;
  RenderedCapture rendered;
  rendered.backend = choice.backend;
  rendered.device = choice.renderer->description();
  rendered.result = choice.renderer->render(
      job, first, [&](std::size_t done, std::size_t total, const std::string& what) {
        progress.update(done, total, what);
      });
  throwIfInterrupted();  // a Ctrl-C during the last segment still means "stop"
  rendered.result.nonFiniteRejected = finite.nonFiniteValues();
  if (rendered.result.nonFiniteRejected > 0) {
    warn(std::to_string(rendered.result.nonFiniteRejected) +
         " NaN/infinite volume values written as 0 (transient.json "
         "stats.rejected_non_finite_values)");
  }
  rendered.steady = steady.steady();
  if (psfConfig && consumers.psfOnRaws) {  // the sum over bins of the blurred bins, by linearity
    Image& s = rendered.steady;
    optics::applyPsf(psfConfig->kernel, s.data.data(), static_cast<std::size_t>(s.channels),
                     {s.width, s.height, static_cast<std::size_t>(s.channels), 1},
                     {optics::PsfMethod::Auto, config.cpu_threads});
  }
  // The light on the axis in the terms of the light the renderer counted off
  // it: before the vignetting's gains (with a gain after it on the axis and
  // before it off it, an all-zero map made all the light "late").
  rendered.result.onAxisEnergy = vignetted ? vignetted->lightBeforeGain() : sumOf(rendered.steady);
  checkAxisAfterRender(config, job, rendered.result);  // throws under --strict
  return rendered;
}

}  // namespace tofsim::pipeline
