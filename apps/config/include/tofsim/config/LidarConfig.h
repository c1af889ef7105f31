#pragma once
// The `lidar:` section of a run config (issue 43), in place of `camera:` and
// `light:`: a spinning lidar, a raster or a multizone sensor whose beams
// (zones) are captures of their own (core/lidar), its defaults perhaps a
// device preset's (LidarPresets.h). Keys, units and defaults:
// configs/README.md, `lidar`.

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "tofsim/lidar/LidarSpec.h"
#include "tofsim/lidar/MultipathSettings.h"
#include "tofsim/util/Error.h"

namespace tofsim::config {

struct LidarConfig {
  lidar::LidarSpec spec;
  glm::vec3 look_at_world{1.0f, 0.0f, 0.0f};  ///< as written (spec.forward_world follows)
  glm::vec3 up_written{0.0f, 0.0f, 1.0f};     ///< as written (spec.up_world: normalised)
  /// channels: {count, min, max} as written; count 0 when the elevations
  /// were given as a list.
  int32_t channel_count = 0;
  double channel_min_deg = 0.0, channel_max_deg = 0.0;
  /// rotation_rate: turns per second; a beam fires at its azimuth's time
  /// (the point clouds' time_offset). The scene is captured at rest.
  double rotation_rate_Hz = 10.0;
  /// frame_rate (scan: raster): frames per second; the cells fire line by
  /// line over the frame (core/lidar RollingScan.h): the points'
  /// time_offset, and with `sequence` each cell's firing time.
  double frame_rate_Hz = 10.0;
  /// The rate the beams' firing times follow: turns (spinning) or frames
  /// (raster) per second (a zone scan's flood fires once).
  double scanRate_Hz() const {
    return spec.scan == lidar::ScanPattern::Raster ? frame_rate_Hz : rotation_rate_Hz;
  }
  /// plot_beams: the beams (ring, azimuth index) whose waveforms
  /// waveforms.png draws, as [ring, azimuth in degrees] pairs resolved to
  /// the nearest azimuth.
  std::vector<std::array<int32_t, 2>> plot_beams;
  /// multipath: each beam's light that bounces before it returns (its
  /// render-derived fields, the clamps and the seed, are filled by the run).
  lidar::MultipathSettings multipath;
  FileLoc at;  ///< where `lidar:` is
  /// lidar.preset: the device preset whose values were the defaults
  /// (LidarPresets.h); empty: none.
  std::string preset;
};

/// "gaussian" / "tophat"; "first" ... "all".
const char* beamProfileName(lidar::BeamProfile profile);
const char* returnModeName(lidar::ReturnMode mode);
/// "spinning" / "raster" / "zones".
const char* scanPatternName(lidar::ScanPattern scan);

}  // namespace tofsim::config
