#include "NlosRun.h"

#include <nlohmann/json.hpp>

#include "NlosFirstBounce.h"
#include "NlosPictures.h"
#include "NlosSensors.h"
#include "NlosTalFile.h"
#include "RenderStatsJson.h"
#include "RunFolder.h"
#include "SensorParametersJson.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/NlosEstimate.h"
#include "tofsim/pipeline/NlosRender.h"
#include "tofsim/pipeline/NlosScan.h"
#include "tofsim/pipeline/OutputEstimate.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/Version.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {

nlohmann::ordered_json vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }

std::vector<std::string> hAxes(const NlosScanGeometry& scan) {
  if (scan.scan == config::NlosScan::Exhaustive) return {"t", "lx", "ly", "sx", "sy"};
  return {"t", "sx", "sy"};
}

std::string nlosMetadataJson(const config::RunConfig& config, const NlosScanGeometry& scan,
                             const NlosVolume& volume, const std::vector<std::string>& files) {
  const config::NlosConfig& nlos = *config.nlos;
  nlohmann::ordered_json j;
  j["format"] = "tofsim nlos capture";
  j["tofsim_version"] = kVersion;
  j["files"] = files;
  j["scan"] = config::nlosScanName(nlos.scan);
  j["shape"] = volume.shape;
  j["axes"] = hAxes(scan);
  j["axes_doc"] =
      "H[t][sx][sy] (single, confocal) or H[t][lx][ly][sx][sy] (exhaustive): time bin t, laser "
      "point (lx, ly), sensor point (sx, sy) of the grids (x index major, x along the wall's "
      "x_axis, y along its y_axis); float32, C order; y-tal's T_Sx_Sy / T_Lx_Ly_Sx_Sy";
  j["value_unit"] = "W m^-2 sr^-1";
  j["first_bounce_doc"] =
      "first_bounce.npy (H's shape): the laser spot's own return, the spot's radiance averaged "
      "over the sensor point's grid cell where the cell holds the spot (every point of a confocal "
      "scan), in the bin of its path; not in H or capture.hdf5; the sensors see H + first_bounce";
  j["pictures_doc"] =
      "H_steady.png: H summed over time (the wall's steady image, x right, y up); H_xt.png and "
      "H_yt.png: H summed over the wall's y and x, rows the optical path (bins summed in groups "
      "past 2048 rows); laser points summed; colour-mapped views of H, not its numbers";
  j["value_doc"] =
      "radiance at the sensor point towards sensor_origin arriving within the bin, summed over "
      "R, G and B (as tal render's H), for an impulse of the laser at t = 0; only light that "
      "left the wall at the laser spot and came back (the spot's own direct return is not in H)";
  j["time"] = timeAxisJson(volume.axis);
  j["t_start_m"] = volume.axis.start_m();
  j["delta_t_m"] = volume.axis.bin_width_m();
  j["t_accounts_first_and_last_bounces"] = nlos.account_first_and_last_bounces;
  j["time_doc"] =
      nlos.account_first_and_last_bounces
          ? "optical path from laser_origin to the sensor point's return at sensor_origin"
          : "optical path from the laser spot l on the wall to the sensor point s (the legs "
            "laser_origin -> l and s -> sensor_origin are not counted)";
  j["relay_wall"] = {{"name", scan.wall.name},          {"centre", vec(scan.wall.centre_world)},
                     {"x_axis", vec(scan.wall.x_axis)}, {"y_axis", vec(scan.wall.y_axis)},
                     {"normal", vec(scan.wall.normal)}, {"width_m", scan.wall.width_m},
                     {"height_m", scan.wall.height_m}};
  j["sensor_origin"] = vec(scan.sensorOrigin);
  j["laser_origin"] = vec(scan.laserOrigin);
  j["sensor_grid"] = scan.sensorGrid;
  j["laser_grid"] = scan.laserGrid;
  j["laser_power_W"] = vec(nlos.laser_power_W);
  j["laser_falloff"] =
      nlos.laser_falloff == config::LaserFalloff::Projector ? "projector" : "collimated";
  j["renderer"] = config.renderer == config::RendererKind::Reference ? "reference" : "ir";
  j["stats"] = nlosStatsJson(volume);
  return j.dump(2) + "\n";
}

void writeOutputs(const config::RunConfig& config, const NlosScanGeometry& scan,
                  const NlosVolume& volume, const std::vector<float>& firstBounce,
                  const std::filesystem::path& dir,
                  const Progress& progress, RunSummary& summary) {
  const auto grid = [](const std::array<int32_t, 2>& g) {
    return io::NpyShape{std::size_t(g[0]), std::size_t(g[1]), 3};
  };
  std::vector<std::string>& files = summary.files;
  if (config.output.transient) {
    io::writeNpy(dir / "H.npy", volume.shape, volume.H.data());
    files.push_back("H.npy");
    io::writeNpy(dir / "first_bounce.npy", volume.shape, firstBounce.data());
    files.push_back("first_bounce.npy");
  }
  for (std::string& f : writeNlosPictures(dir, volume)) files.push_back(std::move(f));
  io::writeNpy(dir / "sensor_grid_xyz.npy", grid(scan.sensorGrid),
               flatXyz(scan.sensorPoints).data());
  files.push_back("sensor_grid_xyz.npy");
  io::writeNpy(dir / "laser_grid_xyz.npy", grid(scan.laserGrid), flatXyz(scan.laserPoints).data());
  files.push_back("laser_grid_xyz.npy");
  if (config.nlos->hdf5) {
    io::writeTalCapture(dir / "capture.hdf5", talCaptureOf(config, scan, volume));
    files.push_back("capture.hdf5");
  }
  for (std::string& f : runNlosSensors(config, scan, volume, firstBounce, dir, progress)) {
    files.push_back(std::move(f));
  }
  std::vector<std::string> listed = files;
  listed.push_back("config.effective.yaml");
  writeFileAtomically(dir / "H.json", nlosMetadataJson(config, scan, volume, listed));
  files.push_back("H.json");
}

}  // namespace

RunSummary runNlosRender(const config::RunConfig& config, PreparedRenderer& prepared,
                         const RunOptions& options) {
  Progress progress("render", options.quiet);
  checkNlosMemory(config);  // from the config alone: before the scene loads
  prepared.prepare(config);
  const scene::Scene& scene = prepared.scene();
  const NlosScanGeometry scan = planNlosScan(config, scene);
  RunFolder folder(config, options, nlosOutputs(config), progress);
  RunSummary summary;
  summary.outputDirectory = folder.path();
  const NlosVolume volume =
      renderNlosScan(config, scene, scan, prepared,
                     [&](std::size_t done, std::size_t total, const std::string& what) {
                       progress.update(done, total, what);
                     });
  summary.backend = volume.backend;
  summary.device = volume.device;
  summary.result.seconds = volume.seconds;
  summary.result.vpls = volume.vpls;
  progress.message("nlos: " + std::to_string(volume.captures) + " laser position(s), " +
                   std::to_string(volume.scenePreparations) + " scene preparation(s)");
  const std::vector<float> firstBounce = nlosFirstBounce(config, scan, scene, volume.axis);
  writeOutputs(config, scan, volume, firstBounce, folder.staging(), progress, summary);
  folder.finish(config, options, summary.files);  // the effective config H.json lists, last
  return summary;
}

}  // namespace tofsim::pipeline
