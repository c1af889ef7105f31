#pragma once
// Private to the config module: the `nlos:` section's parameter table (see
// RunFields.h). The vectors are Custom entries, parsed in NlosConfigParser.cpp.

#include <array>
#include <tuple>

#include "tofsim/config/NlosConfig.h"
#include "tofsim/sensors/ParamField.h"

namespace tofsim::config {

inline constexpr std::array<sensors::Name<NlosScan>, 3> kNlosScanNames{
    {{"single", NlosScan::Single},
     {"confocal", NlosScan::Confocal},
     {"exhaustive", NlosScan::Exhaustive}}};
inline constexpr std::array<sensors::Name<LaserFalloff>, 2> kLaserFalloffNames{
    {{"collimated", LaserFalloff::Collimated}, {"projector", LaserFalloff::Projector}}};

// clang-format off
inline constexpr auto kNlosFields = std::tuple{
    sensors::Field{"relay_wall", &NlosConfig::relay_wall, sensors::Text{},
          {.doc = "name of the glTF node (or mesh) that is the relay wall: planar, lit and seen on its front face (counter-clockwise winding); its frame is y-tal's: x to the right seen from the front, y = the world's +y in its plane, normal out of the front", .unset = "required"}},
    sensors::Field{"scan", &NlosConfig::scan, sensors::Choice<NlosScan>{kNlosScanNames},
          {.doc = "`single`: one laser spot (`laser_point`), H (t, sx, sy); `confocal`: the laser spot on each sensor point in turn, H (t, sx, sy); `exhaustive`: every laser grid point x every sensor point, H (t, lx, ly, sx, sy)"}},
    sensors::Custom{"sensor_grid", "[int, int]", "each in [1, 4096]", "[16, 16]", "points",
          "sensor points along the wall's x and y, at the centres of a regular grid over the whole wall (tal's `get_grid_xyz`)"},
    sensors::Custom{"laser_grid", "[int, int]", "each in [1, 4096]", "[1, 1]", "points",
          "`exhaustive`: laser points along x and y over the laser aperture"},
    sensors::Custom{"laser_point", "[u, v]", "in [0, 1]", "[0.5, 0.5]", "-",
          "`single`: the laser spot, as a fraction of the wall's width and height from its -x / -y corner"},
    sensors::Custom{"laser_aperture", "[[u0, v0], [u1, v1]]", "0 <= u0 < u1 <= 1, same for v", "[[0, 0], [1, 1]]", "-",
          "`exhaustive`: the sub-rectangle of the wall the laser grid covers (tal's `laser_aperture_{start,end}_{x,y}`)"},
    sensors::Custom{"sensor_origin", "vec3", "in front of the wall", "required", "m",
          "where the SPAD or streak camera focused on the sensor points stands"},
    sensors::Custom{"laser_origin", "vec3", "in front of the wall", "required", "m",
          "where the laser stands"},
    sensors::Custom{"laser_power", "number or vec3 >= 0", "", "1", "W",
          "laser power per channel (R, G, B); the spot at l is a Lambertian emitter of intensity albedo(l) x power x cos / pi"},
    sensors::Field{"laser_falloff", &NlosConfig::laser_falloff, sensors::Choice<LaserFalloff>{kLaserFalloffNames},
          {.doc = "`collimated`: the spot gets `laser_power` wherever it is; `projector`: power x pi cos(theta_L) / d_L^2, as tal render's projector with irradiance `laser_power` (for bin-for-bin comparisons with `tal render`)"}},
    sensors::Field{"account_first_and_last_bounces", &NlosConfig::account_first_and_last_bounces, sensors::Flag{},
          {.doc = "y-tal's `t_accounts_first_and_last_bounces`: `false` times the path from the laser spot to the sensor point only (the field's convention); `true` adds the legs from `laser_origin` to the laser spot and from the sensor point to `sensor_origin`"}},
    sensors::Field{"hdf5", &NlosConfig::hdf5, sensors::Flag{},
          {.doc = "also write `capture.hdf5` in y-tal's layout (`tal.io.read_capture` loads it)"}},
};
// clang-format on

}  // namespace tofsim::config
