#pragma once
// Private to the config module: `camera.psf`, the lens's point spread
// function (config::PsfConfig): the parametric core and halo, or a measured
// kernel in a .npy file. Every bad value is an InputError at its key, a bad
// kernel value naming its file and (y, x).

#include <cstdint>

#include "ConfigNode.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::config {

/// The `psf` mapping of the camera node `camera`, for an image of width x
/// height pixels (the parametric kernel is cropped to it).
PsfConfig parsePsf(const ConfigNode& camera, int32_t width, int32_t height);

}  // namespace tofsim::config
