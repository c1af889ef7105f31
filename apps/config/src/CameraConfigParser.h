#pragma once
// Private to the config module: the `camera` section: pose, field of view
// or a calibrated lens (LensConfig.h), resolution, vignetting and the lens's
// PSF (PsfConfig.h).

#include "ConfigNode.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::config {

void parseCamera(const ConfigNode& node, CameraConfig& out);

}  // namespace tofsim::config
