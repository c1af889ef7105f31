#include "SensorPasses.h"

#include <string>
#include <vector>

#include "tofsim/pipeline/PixelSpanSink.h"
#include "tofsim/util/Interrupt.h"

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
  for (std::size_t i = 1; i < offsets.size(); ++i) {
    throwIfInterrupted();
    progress.message("sensor pass " + std::to_string(i) + "/" + std::to_string(offsets.size() - 1) +
                     " at +" + std::to_string(offsets[i] * 1e3) + " ms");
    const capture::RenderJob job = frame.jobAt(offsets[i]);
    sensors.beginPass(offsets[i]);
    renderCapture(config, job, *frame.renderer, consumers, progress);
  }
  if (offsets.size() > 1) frame.jobAt(0.0);
  sensors.beginPass(0.0);
}

}  // namespace tofsim::pipeline
