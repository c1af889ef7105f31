// _render of an nlos config: the scan's H and grids as NumPy arrays, rendered
// in memory (pipeline::renderNlosScan) or, with an output folder, by the
// CLI's run (pipeline::runRender) and read back from H.npy.

#include "NlosBinding.h"

#include <pybind11/stl.h>

#include <algorithm>

#include "Arrays.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/ConfiguredScene.h"
#include "tofsim/pipeline/NlosRender.h"
#include "tofsim/pipeline/NlosScan.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/RenderRun.h"
#include "tofsim/pipeline/RenderStats.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/Interrupt.h"

namespace py = pybind11;

namespace tofsim::python {

namespace {

py::list vec(const glm::vec3& v) {
  py::list l;
  for (int i = 0; i < 3; ++i) l.append(v[i]);
  return l;
}

std::vector<py::ssize_t> shapeOf(const std::vector<std::size_t>& s) { return {s.begin(), s.end()}; }

}  // namespace

py::dict renderNlos(const config::RunConfig& config, const std::optional<std::string>& outputDir,
                    bool quiet) {
  pipeline::NlosScanGeometry scan;
  pipeline::NlosVolume volume;
  std::vector<std::string> files;
  {
    py::gil_scoped_release released;
    const scene::Scene scene = pipeline::loadConfiguredScene(config);
    scan = pipeline::planNlosScan(config, scene);
    if (outputDir) {
      pipeline::RunOptions options;
      options.outputDirectory = *outputDir;
      options.quiet = quiet;
      const pipeline::RunSummary summary = pipeline::runRender(config, options);
      files = summary.files;
      volume.axis = config.render.time;
      volume.seconds = summary.result.seconds;
      volume.vpls = summary.result.vpls;
      volume.device = summary.device;
      volume.captures = scan.captureCount();
      if (std::find(files.begin(), files.end(), "H.npy") != files.end()) {
        io::NpyArray h = io::readNpy(summary.outputDirectory / "H.npy");
        volume.shape = h.shape;
        volume.H = std::move(h.data);
      }
    } else {
      pipeline::Progress progress("render", quiet);
      volume = pipeline::renderNlosScan(
          config, scene, scan, [&](std::size_t done, std::size_t total, const std::string& what) {
            progress.update(done, total, what);
          });
    }
    throwIfInterrupted();
  }
  py::dict d;
  d["H"] = volume.H.empty() ? py::object(py::none())
                            : py::object(ownedArray(std::move(volume.H), shapeOf(volume.shape)));
  const bool exhaustive = scan.scan == config::NlosScan::Exhaustive;
  d["H_format"] = exhaustive ? "T_Lx_Ly_Sx_Sy" : "T_Sx_Sy";
  d["scan"] = config::nlosScanName(scan.scan);
  d["sensor_grid_xyz"] =
      ownedArray(pipeline::flatXyz(scan.sensorPoints), {scan.sensorGrid[0], scan.sensorGrid[1], 3});
  d["laser_grid_xyz"] =
      ownedArray(pipeline::flatXyz(scan.laserPoints), {scan.laserGrid[0], scan.laserGrid[1], 3});
  d["wall_normal"] = vec(scan.wall.normal);
  d["sensor_xyz"] = vec(scan.sensorOrigin);
  d["laser_xyz"] = vec(scan.laserOrigin);
  d["t_accounts_first_and_last_bounces"] = config.nlos->account_first_and_last_bounces;
  d["time"] = timeAxisDict(volume.axis);
  // H.json's stats (one writer), and the name the time had here before.
  py::dict stats = py::module_::import("json").attr("loads")(pipeline::nlosStatsText(volume));
  stats["seconds"] = volume.seconds;
  d["stats"] = stats;
  d["device"] = volume.device;
  d["files"] = files;
  return d;
}

}  // namespace tofsim::python
