#pragma once
// Turns a config and its loaded scene into a render job: picks the glTF
// camera when the config names one, and mounts the light on the camera when
// asked.

#include "tofsim/capture/RenderJob.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::pipeline {

/// Throws InputError (with the config file and key) when the named glTF
/// camera does not exist.
capture::RenderJob makeRenderJob(const config::RunConfig& config, const scene::Scene& scene);

}  // namespace tofsim::pipeline
