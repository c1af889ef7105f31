#include "LidarSequence.h"

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "RunFolder.h"
#include "RunRecord.h"
#include "LidarFiles.h"
#include "LidarRun.h"
#include "SequenceFrame.h"
#include "SequenceRun.h"
#include "tofsim/config/LidarConfig.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/lidar/BeamBackscatter.h"
#include "tofsim/lidar/LidarReturns.h"
#include "tofsim/lidar/RollingScan.h"
#include "tofsim/pipeline/ConfiguredScene.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/scene/AnimatedScene.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Interrupt.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string frameFolder(std::size_t k) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05zu", k);
  return name;
}

}  // namespace

RunSummary runLidarSequence(const config::RunConfig& config, const RunOptions& options) {
  const config::SequenceConfig& seq = *config.sequence;
  const config::LidarConfig& lidar = *config.lidar;
  Progress progress("sequence", options.quiet);
  scene::LoadReport report;
  const scene::AnimatedScene animated = scene::AnimatedScene::load(config.scene_file, &report);
  reportLoad(report, progress, true);
  checkFrameTimes(seq, animated, config.scene_file);
  scene::Scene rest = animated.restScene();
  configureScene(config, rest, report);

  RunFolder folder(config, options, lidarOutputs(config), progress);
  RunSummary summary;
  summary.outputDirectory = folder.path();

  const int threads = resolveThreads(config.cpu_threads);
  std::vector<physics::ScatterVertex> materials =
      ir::materialVertices(rest, ir::vertexModelOf(config.render.materials));
  lidar::AnimatedWaveformScene moving(animated, std::move(rest), std::move(materials),
                                      config.render.medium, threads);
  const lidar::SceneAtTime sceneAt = [&](double t_s) -> const lidar::WaveformScene& {
    return moving.at(t_s);
  };
  // As a still frame (LidarRun.cpp): the dense volume where something reads
  // or adds to it.
  const double rate_Hz = lidar.scanRate_Hz();
  const lidar::MultipathSettings multipath = lidarMultipath(config);
  const bool backscatter = hasBeamBackscatter(config);
  const bool keepVolume = !config.sensors.empty() || multipath.enabled() || backscatter;
  json frames = json::array();
  for (std::size_t k = 0; k < seq.times_s.size(); ++k) {
    const double t = seq.times_s[k];
    progress.message("frame " + std::to_string(k + 1) + "/" + std::to_string(seq.times_s.size()) +
                     ": the turn from t = " + std::to_string(t) + " s");
    const auto start = std::chrono::steady_clock::now();
    lidar::LidarWaveforms waveforms = lidar::renderRollingWaveforms(
        lidar.spec, sceneAt, config.render.time, t, rate_Hz, threads, keepVolume);
    // The multipath and the medium's backscatter, each beam's at its own time.
    const lidar::BeamSurfaces surfaces = lidar::addRollingLight(
        lidar.spec, multipath, sceneAt, config.render.time, t, rate_Hz, threads, waveforms);
    const lidar::LidarReturns returns =
        lidar::lidarReturns(lidar.spec, waveforms, rate_Hz, threads);
    const std::vector<uint8_t> fog =
        backscatter ? lidar::fogReturnFlags(lidar.spec, waveforms.volume, surfaces)
                    : std::vector<uint8_t>{};
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    throwIfInterrupted();
    config::RunConfig frameConfig = config;
    frameConfig.render.seed = sequenceFrameSeed(config.render.seed, k);
    const std::string name = frameFolder(k);
    fs::create_directory(folder.staging() / name);
    LidarFrame frame{&waveforms, &returns, seconds, threads};
    frame.fogReturns = surfaces.bins.empty() ? nullptr : &fog;
    std::vector<std::string> frameFiles =
        writeLidarFiles(frameConfig, frame, folder.staging() / name, progress);
    // The frame's own effective config (its seed), which its lidar.json lists.
    writeRecord(frameConfig, RunOptions{}, folder.staging() / name, frameFiles);
    for (const std::string& f : frameFiles) summary.files.push_back(name + "/" + f);
    frames.push_back(
        {{"index", k}, {"time_s", t}, {"seed", frameConfig.render.seed}, {"folder", name}});
  }
  const bool raster = lidar.spec.scan == lidar::ScanPattern::Raster;
  const json doc = {{"frames", frames},
                    {"count", seq.times_s.size()},
                    {raster ? "frame_rate_Hz" : "rotation_rate_Hz", rate_Hz},
                    {"doc", raster ? "frame k: the raster's frame from time_s, cell (row, column) "
                                  "fired at time_s + ((rows - 1 - row) columns + column) / "
                                  "(rows columns frame_rate_Hz) against the scene there (the "
                                  "points' time_offset)"
                                : "frame k: the lidar's turn from time_s, azimuth column a fired "
                                  "at time_s + (azimuth_a - azimuth_start) / 360 / rotation_rate_Hz "
                                  "against the scene there (the points' time_offset)"},
                    {"animation_start_s", animated.start_s()},
                    {"animation_end_s", animated.end_s()}};
  writeFileAtomically(folder.staging() / "sequence.json", doc.dump(2) + "\n");
  summary.files.push_back("sequence.json");
  summary.backend = "cpu";
  summary.device = "CPU (" + std::to_string(threads) + " threads, Embree)";
  throwIfInterrupted();
  folder.finish(config, options, summary.files);
  return summary;
}

}  // namespace tofsim::pipeline
