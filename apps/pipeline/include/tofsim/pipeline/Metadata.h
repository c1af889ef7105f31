#pragma once
// transient.json: how to read transient.npy without guessing. Axis order,
// units, the time axis in seconds and in metres of optical path, the camera,
// the light, channel names, the tofsim version and the seed.

#include <string>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::pipeline {

std::string transientMetadataJson(const config::RunConfig& config, const capture::RenderJob& job,
                                  const capture::RenderResult& result);

}  // namespace tofsim::pipeline
