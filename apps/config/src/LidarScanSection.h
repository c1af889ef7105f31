#pragma once
// Private to the config module: the lidar's device preset (`lidar.preset`,
// LidarPresets.h) and its scan (`lidar.scan`: spinning, raster or zones, a
// grid scan's `grid`, `field_of_view` and `zone_rays`), with located errors
// (an unknown preset, a grid of no rows, a key of another scan). Called by
// parseLidarView (LidarSection.h) before the lidar's other keys.

#include "ConfigNode.h"
#include "tofsim/config/LidarConfig.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::config {

/// lidar.preset: its values become `out`'s and `time`'s bins (parseTime
/// runs after, so explicit keys win); nothing without the key.
void applyLidarPreset(const ConfigNode& lidarNode, LidarConfig& out, TimeAxis& time);

/// lidar.scan (default: the preset's, else spinning), a grid scan's keys,
/// and a located error for a key that belongs to another scan.
void parseLidarScan(const ConfigNode& lidarNode, lidar::LidarSpec& spec);

}  // namespace tofsim::config
