#include "LidarRun.h"

#include <chrono>

#include "KeptAcrossRenders.h"
#include "LidarFiles.h"
#include "StagedOutput.h"
#include "tofsim/pipeline/AxisReport.h"
#include "tofsim/config/LidarConfig.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/lidar/BeamBackscatter.h"
#include "tofsim/pipeline/Manifest.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/util/Interrupt.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::pipeline {

OutputEstimate lidarOutputs(const config::RunConfig& config) {
  const lidar::LidarSpec& s = config.lidar->spec;
  const auto beams = static_cast<std::uintmax_t>(s.channels()) * s.azimuths();
  const std::string keys = "lidar.channels x lidar.azimuth";
  OutputEstimate e;
  if (config.output.transient) {
    e.items.push_back({"waveforms.npy", beams * config.render.time.bins * 4,
                       keys + " x time.bins"});
  }
  e.items.push_back({"range, intensity, beam_directions (npy, exr)", beams * 4 * 8, keys});
  e.items.push_back({"points.ply, points.pcd", beams * s.returns.max * 27 * 2,
                     keys + " x lidar.returns.max"});
  if (config.render.medium.scatters()) {  // the medium's false returns alone
    e.items.push_back({"fog_points.ply", beams * s.returns.max * 27, keys + " x lidar.returns.max"});
  }
  for (const sensors::SensorSpec& spec : config.sensors) {
    // Bounded as a camera's: its bins and a few arrays per beam.
    e.items.push_back({"sensors/" + spec.name, beams * config.render.time.bins * 4 * 2,
                       keys + " x the sensor's bins"});
  }
  return e;
}

namespace {

// As a camera render's check after it (AxisReport.h), for the beams.
void warnLightOffTheAxis(const lidar::LidarWaveforms& w, const Progress& progress) {
  double onAxis = 0.0;
  for (float v : w.volume.values()) onAxis += v;
  const double total = onAxis + w.lost.before + w.lost.after;
  if (!(total > 0.0)) return;
  const auto percent = [&](double v) { return std::to_string(100.0 * v / total) + " %"; };
  if (w.lost.after > kWindowLossWarning * total) {
    progress.message("warning: " + percent(w.lost.after) +
                     " of the lidar's light arrives after the last bin: raise time.bins");
  }
  if (w.lost.before > kWindowLossWarning * total) {
    progress.message("warning: " + percent(w.lost.before) +
                     " of the lidar's light arrives before the first bin: lower time.start");
  }
}

}  // namespace

RunSummary runLidarRender(const config::RunConfig& config, PreparedRenderer& prepared,
                          const RunOptions& options) {
  Progress progress("render", options.quiet);
  prepared.prepare(config);
  const scene::Scene& scene = prepared.scene();
  RunSummary summary;
  summary.outputDirectory =
      options.outputDirectory.empty() ? config.output.directory : options.outputDirectory;
  StagedFolder folder(summary.outputDirectory, keptAcrossRenders);
  noteLinkedOutput(folder, progress);
  checkOutputsFit(lidarOutputs(config), config, folder.staging());

  const auto start = std::chrono::steady_clock::now();
  const int threads = resolveThreads(config.cpu_threads);
  const rays::RayScene rays(scene, threads);
  lidar::WaveformScene traced{&rays,
                              ir::materialVertices(scene, ir::vertexModelOf(config.render.materials)),
                              config.render.medium};
  lidar::LidarWaveforms waveforms =
      lidar::renderDirectWaveforms(config.lidar->spec, traced, config.render.time, threads);
  // The medium's backscatter (BeamBackscatter.h): nothing without a scattering medium.
  const lidar::BeamSurfaces surfaces = lidar::addBackscatter(
      config.lidar->spec, traced, config.render.time, threads, waveforms);
  const lidar::LidarReturns returns =
      lidar::lidarReturns(config.lidar->spec, waveforms.volume, config.lidar->rotation_rate_Hz);
  const std::vector<uint8_t> fog = lidar::fogReturnFlags(config.lidar->spec, waveforms.volume, surfaces);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.backend = "cpu";
  summary.device = "CPU (" + std::to_string(threads) + " threads, Embree)";
  summary.result.seconds = seconds;
  progress.message("lidar: " + std::to_string(config.lidar->spec.channels()) + " x " +
                   std::to_string(config.lidar->spec.azimuths()) + " beams, " +
                   std::to_string(returns.points.size()) + " returns");
  warnLightOffTheAxis(waveforms, progress);
  throwIfInterrupted();
  LidarFrame frame{&waveforms, &returns, seconds, threads};
  frame.fogReturns = surfaces.bins.empty() ? nullptr : &fog;
  summary.files = writeLidarFiles(config, frame, folder.staging(), progress);
  if (options.batchManifest) {  // last: it exists only once the files it lists do
    writeManifest(folder.staging(), options.batchManifest->runName, summary.files,
                  options.batchManifest->inputs);
    summary.files.push_back(kManifestName);
  }
  throwIfInterrupted();
  commitOutput(folder, progress);
  return summary;
}

}  // namespace tofsim::pipeline
