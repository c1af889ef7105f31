#pragma once
// Private to the config module: a `rays:` mapping in place of `camera:` (a
// capture whose pixels are the user's own rays: a fibre bundle, a scanning
// pattern, a custom lens), its file read into capture::RayListImager. The
// file is a .npy of shape (N, 6), float32 or float64, or a CSV of six
// columns ox, oy, oz, dx, dy, dz (metres, world frame; a '#' line a
// comment, a first row that is not numbers a header), one ray a row. It is
// opened without following links. Directions are normalised; a zero or
// non-finite one is a located error naming the file and its row (line).

#include <string>

#include "ConfigNode.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::config {

/// rays: {file, resolution: [width, height] (default [N, 1]), last_leg_counts}
/// (RaysFields.h); RaysConfig::file is the ray file's absolute path.
RaysConfig parseRays(const ConfigNode& rays);

}  // namespace tofsim::config
