#include "LidarRun.h"

#include <chrono>

#include "LidarFiles.h"
#include "LidarSequence.h"
#include "RunFolder.h"
#include "tofsim/pipeline/AxisReport.h"
#include "tofsim/config/LidarConfig.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/lidar/BeamBackscatter.h"
#include "tofsim/lidar/MultipathWaveforms.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/lidar/ZoneWaveforms.h"
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
  if (hasBeamBackscatter(config)) {  // the medium's false returns alone
    e.items.push_back({"fog_points.ply", beams * s.returns.max * 27, keys + " x lidar.returns.max"});
  }
  for (const sensors::SensorSpec& spec : config.sensors) {
    // Bounded as a camera's: its bins and a few arrays per beam.
    e.items.push_back({"sensors/" + spec.name, beams * config.render.time.bins * 4 * 2,
                       keys + " x the sensor's bins"});
  }
  if (config.sequence) {  // a rolling scan's frames, each a frame's files (LidarSequence.h)
    for (OutputItem& item : e.items) {
      item.bytes *= config.sequence->times_s.size();
      item.drivenBy += " x the sequence's frames";
    }
  }
  return e;
}

lidar::MultipathSettings lidarMultipath(const config::RunConfig& config) {
  lidar::MultipathSettings m = config.lidar->multipath;
  m.geometry_clamp_per_m2 = config.render.indirect.geometry_term_clamp_per_m2;
  m.brdf_clamp_per_sr = config.render.indirect.vpl_brdf_clamp_per_sr;
  m.vertex_model = ir::vertexModelOf(config.render.materials);
  m.seed = config.render.seed;
  return m;
}

namespace {

// As a camera render's check after it (AxisReport.h), for the beams.
void warnLightOffTheAxis(const lidar::LidarWaveforms& w, const Progress& progress) {
  double onAxis = 0.0;
  if (w.volume.size() > 0) {
    for (float v : w.volume.values()) onAxis += v;
  } else {
    onAxis = w.sparse.total();  // the same sum
  }
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
  if (config.sequence) return runLidarSequence(config, options);  // a rolling scan per frame
  Progress progress("render", options.quiet);
  prepared.prepare(config);
  const scene::Scene& scene = prepared.scene();
  RunFolder folder(config, options, lidarOutputs(config), progress);
  RunSummary summary;
  summary.outputDirectory = folder.path();

  const auto start = std::chrono::steady_clock::now();
  const int threads = resolveThreads(config.cpu_threads);
  const rays::RayScene rays(scene, threads);
  lidar::WaveformScene traced{&rays,
                              ir::materialVertices(scene, ir::vertexModelOf(config.render.materials)),
                              config.render.medium};
  // The dense volume only where something reads or adds to it: the sensors,
  // the multipath and the medium's backscatter (added after the render) and
  // the zones (ZoneWaveforms.h: the flood's light over each zone's solid
  // angle, always dense). Else waveforms.npy is streamed from the beams'
  // nonzero bins and the returns found on them (LidarWaveforms::beamWaveform,
  // lidarReturns).
  const lidar::LidarSpec& spec = config.lidar->spec;
  const bool zones = spec.scan == lidar::ScanPattern::Zones;
  const bool backscatter = hasBeamBackscatter(config);
  const bool keepVolume =
      !config.sensors.empty() || config.lidar->multipath.enabled() || backscatter;
  lidar::LidarWaveforms waveforms =
      zones ? lidar::renderZoneWaveforms(spec, traced, config.render.time, threads)
            : lidar::renderDirectWaveforms(spec, traced, config.render.time, threads, keepVolume);
  lidar::addMultipathWaveforms(spec, lidarMultipath(config), traced, config.render.time, threads,
                               waveforms);
  // The medium's backscatter along each beam's (zone's) receiver rays
  // (BeamBackscatter.h): nothing without a scattering medium.
  const lidar::BeamSurfaces surfaces =
      backscatter ? lidar::addBackscatter(spec, traced, config.render.time, threads, waveforms)
                  : lidar::BeamSurfaces{};
  const lidar::LidarReturns returns =
      lidar::lidarReturns(spec, waveforms, config.lidar->scanRate_Hz(), threads);
  const std::vector<uint8_t> fog =
      backscatter ? lidar::fogReturnFlags(spec, waveforms.volume, surfaces) : std::vector<uint8_t>{};
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
  folder.finish(config, options, summary.files);
  return summary;
}

}  // namespace tofsim::pipeline
