#include "SensorPasses.h"

#include <memory>
#include <string>
#include <vector>

#include "tofsim/pipeline/CaptureLoop.h"
#include "tofsim/pipeline/PixelSpanSink.h"

namespace tofsim::pipeline {

void renderSensorPasses(const config::RunConfig& config, const SequenceFrame& frame,
                        SensorStreams& sensors, const CaptureConsumers& like,
                        std::optional<int32_t> bounces, Progress& progress) {
  const std::vector<double> offsets = sensors.passOffsets_s();
  PixelSpanSink spans([&](const sensors::PixelSpan& s) { sensors.consume(s); },
                      bounces.value_or(0));
  CaptureConsumers consumers;
  consumers.sinks = {&spans};
  consumers.bounces = like.bounces;
  consumers.psfOnRaws = like.psfOnRaws;
  // Each pass a capture of the loop at its time: the scene moved there.
  const std::size_t passes = offsets.empty() ? 0 : offsets.size() - 1;
  std::optional<RenderedCapture> rendered;  // the sensors took the light
  CaptureLoopOptions loop;
  loop.withinCapture = [&](std::size_t done, std::size_t total, const std::string& what) {
    progress.update(done, total, what);
  };
  renderCaptures(
      *frame.prepared, config, passes,
      [&](std::size_t i) {
        const double at = offsets[i + 1];
        progress.message("sensor pass " + std::to_string(i + 1) + "/" + std::to_string(passes) +
                         " at +" + std::to_string(at * 1e3) + " ms");
        capture::RenderJob job = frame.jobAt(at);
        sensors.beginPass(at);
        return job;
      },
      [&](std::size_t, const capture::RenderJob& job) {
        return std::make_unique<ConsumersSink>(config, job, consumers, rendered);
      },
      loop);
  if (passes > 0) frame.jobAt(0.0);
  sensors.beginPass(0.0);
}

}  // namespace tofsim::pipeline
