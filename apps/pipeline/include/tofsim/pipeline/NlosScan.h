#pragma once
// The geometry of a non-line-of-sight scan (config `nlos:`): the relay wall,
// its sensor and laser grids in y-tal's order, and each capture the scan is
// made of -- one laser spot (a Lambertian emitter on the wall) and the points
// that gather its light, as a point-set imager -- so that the renderer runs
// the scan as a sequence of ordinary captures of one prepared scene.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "tofsim/capture/Imager.h"
#include "tofsim/capture/Light.h"
#include "tofsim/capture/RelayWall.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::pipeline {

/// One laser position of the scan.
struct NlosCapture {
  capture::Light laser;            ///< the spot: a Lambertian light at l, facing the wall's normal
  capture::PointSetImager points;  ///< the sensor points lit by it (one for confocal)
  /// Added to the time axis' start: -(|laser_origin - l|) in time with
  /// account_first_and_last_bounces, so the first leg is on the axis; 0 otherwise.
  double axisShift_s = 0.0;
};

struct NlosScanGeometry {
  config::NlosScan scan = config::NlosScan::Confocal;
  capture::RelayWall wall;
  std::array<int32_t, 2> sensorGrid{1, 1}, laserGrid{1, 1};
  std::vector<glm::vec3> sensorPoints, laserPoints;  ///< x index major (ix * ny + iy)
  glm::vec3 sensorOrigin{0.0f}, laserOrigin{0.0f};

  /// Laser positions: confocal and exhaustive, one per laser point.
  std::size_t captureCount() const { return laserPoints.size(); }
  /// Sensor points each capture gathers: 1 for confocal (the laser's own point).
  std::size_t pointsPerCapture() const;
  /// H's axes after time: {sx, sy}, or {lx, ly, sx, sy} for exhaustive.
  std::vector<std::size_t> pointShape() const;
  /// Capture i (a laser point) as the renderer takes it.
  NlosCapture capture(std::size_t i, const config::RunConfig& config,
                      const scene::Scene& scene) const;
};

/// H's axes after time for a scan of these grids, from the config alone:
/// {sx, sy}, or {lx, ly, sx, sy} for exhaustive scans (NlosEstimate.h).
std::vector<std::size_t> nlosPointShape(config::NlosScan scan, const std::array<int32_t, 2>& sensor,
                                        const std::array<int32_t, 2>& laser);

/// Points as x, y, z floats one after another (the grids' .npy, HDF5 and
/// NumPy layout).
std::vector<float> flatXyz(const std::vector<glm::vec3>& points);

/// The index of relay wall `wallName`'s material in scene.materials (the
/// first mesh whose node or name it is), -1 where the scene has none: the
/// laser spot's surface (capture::Light::surface_material).
int32_t relayWallMaterial(const scene::Scene& scene, const std::string& wallName);

/// The scan a config describes on its scene. Throws InputError at the
/// config's key (file and line) when the wall is missing, not planar or has
/// no area, or when an origin is not in front of the wall.
NlosScanGeometry planNlosScan(const config::RunConfig& config, const scene::Scene& scene);

}  // namespace tofsim::pipeline
