#pragma once
// Everything that can be checked against the device's limits before any
// device work; each message names the config key to change.

#include "tofsim/capture/RenderJob.h"
#include "tofsim/ir/IrBackend.h"

namespace tofsim::ir {

/// Throws InputError naming the key (camera.resolution, time.bins, ...).
void validateJob(const capture::RenderJob& job, const DeviceLimits& limits);

}  // namespace tofsim::ir
