#pragma once
// Private to the config module: issue 43's `lidar:` section, read into
// RunConfig::lidar with located errors (no channels, a zero step, a
// divergence <= 0, an unknown preset, a grid scan without its grid, a key of
// another scan, `lidar` beside `camera`, `light`, `rays` or `nlos`).

#include <yaml-cpp/yaml.h>

#include "ConfigNode.h"
#include "tofsim/config/LidarConfig.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::config {

/// The root's `lidar:` (present) into config.lidar; config.camera.camera's
/// width and height become the azimuths and channels (the sensors' image).
/// A `preset` also sets config.render.time's bins (parsed after).
void parseLidarView(const ConfigNode& root, RunConfig& config);

/// The `output:` and `sequence:` keys a lidar capture does not take.
void checkLidarRun(const ConfigNode& root, const LidarConfig& lidarConfig);

/// The effective config's `lidar:`.
YAML::Node lidarNode(const LidarConfig& lidar);

}  // namespace tofsim::config
