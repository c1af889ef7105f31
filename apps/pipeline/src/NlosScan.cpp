#include "tofsim/pipeline/NlosScan.h"

#include <algorithm>
#include <cmath>

#include "tofsim/scene/Scene.h"
#include "tofsim/util/Error.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::pipeline {

namespace {

// The wall's own albedo at the laser spot: its material's base colour (a
// texture on the wall is not sampled).
glm::vec3 wallAlbedo(const scene::Scene& scene, int32_t material) {
  return material < 0 ? glm::vec3(0.0f) : scene.materials.at(material).albedo;
}

void requireInFront(const capture::RelayWall& wall, const glm::vec3& origin, const FileLoc& at,
                    const char* key) {
  if (!(wall.heightAbove(origin) > 0.0f)) {
    throw InputError(at, std::string("nlos.") + key,
                     "lies behind (or on) relay wall '" + wall.name +
                         "': its front face, by the glTF winding, faces (" +
                         std::to_string(wall.normal.x) + ", " + std::to_string(wall.normal.y) +
                         ", " + std::to_string(wall.normal.z) + ")");
  }
}

}  // namespace

int32_t relayWallMaterial(const scene::Scene& scene, const std::string& wallName) {
  for (const scene::Mesh& m : scene.meshes) {
    if (m.node == wallName || m.name == wallName) return static_cast<int32_t>(m.material);
  }
  return -1;
}

std::size_t NlosScanGeometry::pointsPerCapture() const {
  return scan == config::NlosScan::Confocal ? 1 : sensorPoints.size();
}

std::vector<std::size_t> nlosPointShape(config::NlosScan scan, const std::array<int32_t, 2>& sensor,
                                        const std::array<int32_t, 2>& laser) {
  const std::vector<std::size_t> s{std::size_t(sensor[0]), std::size_t(sensor[1])};
  if (scan != config::NlosScan::Exhaustive) return s;
  return {std::size_t(laser[0]), std::size_t(laser[1]), s[0], s[1]};
}

std::vector<std::size_t> NlosScanGeometry::pointShape() const {
  return nlosPointShape(scan, sensorGrid, laserGrid);
}

NlosCapture NlosScanGeometry::capture(std::size_t i, const config::RunConfig& config,
                                      const scene::Scene& scene) const {
  const config::NlosConfig& nlos = *config.nlos;
  const glm::vec3 l = laserPoints.at(i);
  NlosCapture c;
  // The spot's light leaves the wall: a cosine emitter of the wall's albedo
  // times the power that reaches it, just in front of the plane so that its
  // rays do not start inside the wall.
  const glm::vec3 toLaser = laserOrigin - l;
  const float dLaser = glm::length(toLaser);
  float power = 1.0f;
  if (nlos.laser_falloff == config::LaserFalloff::Projector) {
    const float cosL = glm::dot(wall.normal, toLaser / dLaser);
    power = static_cast<float>(M_PI) * cosL / (dLaser * dLaser);
  }
  c.laser.type = capture::Light::Type::Lambertian;
  const float lift = 1e-5f * std::max({wall.width_m, wall.height_m, 1e-3f});
  c.laser.position_world = l + lift * wall.normal;
  c.laser.direction_world = wall.normal;
  // The spot's light leaves through the wall's scattering delay too: it
  // starts every path's response class (ir::lightResponse).
  c.laser.surface_material = relayWallMaterial(scene, wall.name);
  c.laser.intensity_W_per_sr = wallAlbedo(scene, c.laser.surface_material) * nlos.laser_power_W *
                               (power / static_cast<float>(M_PI));
  c.points.origin_world = sensorOrigin;
  c.points.last_leg_counts = nlos.account_first_and_last_bounces;
  if (scan == config::NlosScan::Confocal) {
    c.points.points_world = {l};
  } else {
    c.points.points_world = sensorPoints;
  }
  c.points.width = static_cast<int32_t>(c.points.points_world.size());
  c.points.height = 1;
  if (nlos.account_first_and_last_bounces) {
    c.axisShift_s = -config.render.time.index_of_refraction * static_cast<double>(dLaser) /
                    kSpeedOfLight_m_per_s;
  }
  return c;
}

std::vector<float> flatXyz(const std::vector<glm::vec3>& points) {
  std::vector<float> out;
  out.reserve(points.size() * 3);
  for (const glm::vec3& p : points) out.insert(out.end(), {p.x, p.y, p.z});
  return out;
}

NlosScanGeometry planNlosScan(const config::RunConfig& config, const scene::Scene& scene) {
  const config::NlosConfig& nlos = *config.nlos;
  NlosScanGeometry g;
  g.scan = nlos.scan;
  try {
    g.wall = capture::relayWallOf(scene, nlos.relay_wall);
  } catch (const InputError& e) {
    throw InputError(nlos.relay_wall_at, "nlos.relay_wall",
                     std::string(e.what()) + " (" + config.scene_file.string() + ")");
  }
  g.sensorOrigin = nlos.sensor_origin;
  g.laserOrigin = nlos.laser_origin;
  requireInFront(g.wall, g.sensorOrigin, nlos.sensor_origin_at, "sensor_origin");
  requireInFront(g.wall, g.laserOrigin, nlos.laser_origin_at, "laser_origin");
  g.sensorGrid = nlos.sensor_grid;
  g.sensorPoints = capture::wallGrid(g.wall, g.sensorGrid[0], g.sensorGrid[1]);
  switch (nlos.scan) {
    case config::NlosScan::Single:
      g.laserPoints = {g.wall.at(nlos.laser_point.x, nlos.laser_point.y)};
      break;
    case config::NlosScan::Confocal:
      g.laserGrid = g.sensorGrid;
      g.laserPoints = g.sensorPoints;
      break;
    case config::NlosScan::Exhaustive:
      g.laserGrid = nlos.laser_grid;
      g.laserPoints = capture::wallGrid(g.wall, g.laserGrid[0], g.laserGrid[1],
                                        nlos.laser_aperture_start, nlos.laser_aperture_end);
      break;
  }
  return g;
}

}  // namespace tofsim::pipeline
