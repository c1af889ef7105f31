#pragma once
// Private to the pipeline: a moving scene's frame seen by sensors that sample
// the light at several times within it (CW-ToF's raws): a render per time
// other than the frame's own, each given to the sensors alone.

#include <cstdint>
#include <optional>

#include "SequenceFrame.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/RenderCapture.h"
#include "tofsim/pipeline/SensorStreams.h"

namespace tofsim::pipeline {

/// The light at the times within the frame at which some sensor samples it
/// (SensorStreams::passOffsets_s), other than the frame's own, through the
/// frame's renderer with the consumers' bounces and PSF path (`like`); then
/// the scene back at the frame's time for the reference pass (moved, and so
/// prepared again, only when it was moved away).
void renderSensorPasses(const config::RunConfig& config, const SequenceFrame& frame,
                        SensorStreams& sensors, const CaptureConsumers& like,
                        std::optional<int32_t> bounces, Progress& progress);

}  // namespace tofsim::pipeline
