#pragma once
// transient.json: how to read transient.npy without guessing. Axis order,
// units, the time axis in seconds and in metres of optical path, the camera,
// the light, the medium (with one), channel names, the tofsim version, the
// seed, and what rendered it (`backend`: gl, cpu or reference; `device`: its
// description).

#include <string>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::pipeline {

std::string transientMetadataJson(const config::RunConfig& config, const capture::RenderJob& job,
                                  const capture::RenderResult& result, const std::string& backend,
                                  const std::string& device);

}  // namespace tofsim::pipeline
