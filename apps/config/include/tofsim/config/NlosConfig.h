#pragma once
// The `nlos:` section of a run config: a non-line-of-sight relay-wall scan in
// the vocabulary of y-tal (tal render's keys, ../shared/research/
// nlos-capture-format.md): which node is the wall, the scan type, the sensor
// and laser grids on it, where the sensor and the laser stand, and whether
// the time axis counts the legs from the laser to the wall and from the wall
// to the sensor.

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::config {

enum class NlosScan { Single, Confocal, Exhaustive };
/// How the laser's power reaches the wall: `collimated` (a real laser: the
/// same power wherever it points) or `projector` (tal render's mitransient
/// projector: power x pi cos(theta_L) / d_L^2, its irradiance parameter).
enum class LaserFalloff { Collimated, Projector };

struct NlosConfig {
  std::string relay_wall;  ///< glTF node (or mesh) name of the planar wall
  NlosScan scan = NlosScan::Confocal;
  std::array<int32_t, 2> sensor_grid{16, 16};  ///< points along the wall's x and y
  std::array<int32_t, 2> laser_grid{1, 1};     ///< exhaustive scans only
  /// single: the laser spot at (u, v) of the wall, in [0, 1]^2 (0: -x / -y edge).
  glm::vec2 laser_point{0.5f, 0.5f};
  /// exhaustive: the laser grid covers this sub-rectangle of the wall (u, v).
  glm::vec2 laser_aperture_start{0.0f}, laser_aperture_end{1.0f};
  glm::vec3 sensor_origin{0.0f};  ///< world; required
  glm::vec3 laser_origin{0.0f};   ///< world; required
  glm::vec3 laser_power_W{1.0f};  ///< per channel
  LaserFalloff laser_falloff = LaserFalloff::Collimated;
  /// y-tal's t_accounts_first_and_last_bounces: false (the field's default)
  /// times a path from the laser spot l to the sensor point s only.
  bool account_first_and_last_bounces = false;
  bool hdf5 = true;  ///< also write capture.hdf5 in y-tal's layout
  /// Where the keys that are checked against the scene were written, for
  /// errors the pipeline finds (a wall that is missing, an origin behind it).
  FileLoc relay_wall_at, sensor_origin_at, laser_origin_at;
};

const char* nlosScanName(NlosScan scan);

}  // namespace tofsim::config
