#pragma once
// Lidar device presets (`lidar.preset: <name>`): generic devices whose
// values come from published datasheets and manuals
// (shared/research/media-delays-lidar.md, section 3: source keys resolve
// there). A preset fills the lidar's defaults (and, for a multizone
// sensor, the histogram's bins: time.bin_width and time.bins) before the
// config's own keys are read: every explicit key wins. A value a preset
// sets without a source is listed as assumed, with what it stands for.
// The same shape as the sensors' presets (sensors/DevicePreset.h).

#include <span>
#include <string>
#include <string_view>

#include "tofsim/config/LidarConfig.h"
#include "tofsim/sensors/DevicePreset.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::config {

/// What a lidar preset sets: the lidar's keys and the render's time axis.
struct LidarDefaults {
  LidarConfig lidar;
  TimeAxis time;
};
using LidarPreset = sensors::DevicePreset<LidarDefaults>;

/// Every lidar preset, in the order the docs list them.
std::span<const LidarPreset> lidarPresets();

/// The preset called `name`, or nullptr.
const LidarPreset* findLidarPreset(std::string_view name);

/// "name (lidar): device" and each value the preset sets (as the effective
/// config writes it) with its source or why it is assumed: `tofsim presets`.
std::string describeLidarPreset(const LidarPreset& preset);

}  // namespace tofsim::config
