#include "NlosTalFile.h"

#include <sstream>

#include "tofsim/pipeline/Version.h"

namespace tofsim::pipeline {

namespace {

io::TalGrid gridOf(const std::array<int32_t, 2>& size, const std::vector<glm::vec3>& points,
                   const glm::vec3& normal) {
  io::TalGrid g;
  g.format = io::TalGridFormat::X_Y_3;
  g.shape = {std::size_t(size[0]), std::size_t(size[1]), 3};
  g.xyz = flatXyz(points);
  g.normals = flatXyz(std::vector<glm::vec3>(points.size(), normal));
  return g;
}

// YAML: the version and seed as keys, the effective config as a block scalar.
std::string sceneInfo(const config::RunConfig& config) {
  std::ostringstream out;
  out << "generator: tofsim\ntofsim_version: " << kVersion << "\nseed: " << config.render.seed
      << "\nH_units: radiance W m^-2 sr^-1 per bin, summed over R, G, B\n"
      << "laser_falloff: "
      << (config.nlos->laser_falloff == config::LaserFalloff::Projector ? "projector"
                                                                        : "collimated")
      << "\nconfig: |\n";
  std::istringstream yaml(config::effectiveConfigYaml(config));
  for (std::string line; std::getline(yaml, line);) out << "  " << line << "\n";
  return out.str();
}

}  // namespace

io::TalCapture talCaptureOf(const config::RunConfig& config, const NlosScanGeometry& scan,
                            const NlosVolume& volume) {
  io::TalCapture t;
  t.H_shape = volume.shape;
  t.H = volume.H;
  t.H_format = scan.scan == config::NlosScan::Exhaustive ? io::TalHFormat::T_Lx_Ly_Sx_Sy
                                                         : io::TalHFormat::T_Sx_Sy;
  t.sensor_xyz = {scan.sensorOrigin.x, scan.sensorOrigin.y, scan.sensorOrigin.z};
  t.laser_xyz = {scan.laserOrigin.x, scan.laserOrigin.y, scan.laserOrigin.z};
  t.sensor_grid = gridOf(scan.sensorGrid, scan.sensorPoints, scan.wall.normal);
  t.laser_grid = gridOf(scan.laserGrid, scan.laserPoints, scan.wall.normal);
  t.delta_t_m = volume.axis.bin_width_m();
  t.t_start_m = volume.axis.start_m();
  t.t_accounts_first_and_last_bounces = config.nlos->account_first_and_last_bounces;
  t.scene_info_yaml = sceneInfo(config);
  return t;
}

}  // namespace tofsim::pipeline
