#include "LidarSequence.h"

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>

#include "KeptAcrossRenders.h"
#include "LidarFiles.h"
#include "LidarRun.h"
#include "SequenceFrame.h"
#include "SequenceRun.h"
#include "StagedOutput.h"
#include "tofsim/config/LidarConfig.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/lidar/LidarReturns.h"
#include "tofsim/lidar/RollingScan.h"
#include "tofsim/pipeline/ConfiguredScene.h"
#include "tofsim/pipeline/Manifest.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/scene/AnimatedScene.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Interrupt.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The scene moved to each column's time, its rays rebuilt there.
class MovingScene {
 public:
  MovingScene(const config::RunConfig& config, const scene::AnimatedScene& animated,
              scene::Scene scene, int threads)
      : animated_(animated), scene_(std::move(scene)), threads_(threads) {
    traced_.materials =
        ir::materialVertices(scene_, ir::vertexModelOf(config.render.materials));
    traced_.medium = config.render.medium;
  }
  const lidar::WaveformScene& at(double t_s) {
    if (!rays_ || t_s != time_s_) {
      rays_.reset();  // it holds the scene: gone before the scene moves
      animated_.updateScene(scene_, t_s);
      rays_.emplace(scene_, threads_);
      traced_.rays = &*rays_;
      time_s_ = t_s;
    }
    return traced_;
  }

 private:
  const scene::AnimatedScene& animated_;
  scene::Scene scene_;
  int threads_;
  std::optional<rays::RayScene> rays_;
  lidar::WaveformScene traced_;
  double time_s_ = 0.0;
};

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

  RunSummary summary;
  summary.outputDirectory =
      options.outputDirectory.empty() ? config.output.directory : options.outputDirectory;
  StagedFolder folder(summary.outputDirectory, keptAcrossRenders);
  noteLinkedOutput(folder, progress);
  OutputEstimate estimate = lidarOutputs(config);
  for (OutputItem& item : estimate.items) {
    item.bytes *= seq.times_s.size();
    item.drivenBy += " x sequence frames";
  }
  checkOutputsFit(estimate, config, folder.staging());

  const int threads = resolveThreads(config.cpu_threads);
  MovingScene moving(config, animated, std::move(rest), threads);
  const lidar::SceneAtTime sceneAt = [&](double t_s) -> const lidar::WaveformScene& {
    return moving.at(t_s);
  };
  json frames = json::array();
  for (std::size_t k = 0; k < seq.times_s.size(); ++k) {
    const double t = seq.times_s[k];
    progress.message("frame " + std::to_string(k + 1) + "/" + std::to_string(seq.times_s.size()) +
                     ": the turn from t = " + std::to_string(t) + " s");
    const auto start = std::chrono::steady_clock::now();
    const lidar::LidarWaveforms waveforms =
        lidar::renderRollingWaveforms(lidar.spec, sceneAt, config.render.time, t,
                                      lidar.rotation_rate_Hz, threads, !config.sensors.empty());
    const lidar::LidarReturns returns =
        lidar::lidarReturns(lidar.spec, waveforms, lidar.rotation_rate_Hz);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    throwIfInterrupted();
    config::RunConfig frameConfig = config;
    frameConfig.render.seed = sequenceFrameSeed(config.render.seed, k);
    const std::string name = frameFolder(k);
    fs::create_directory(folder.staging() / name);
    const LidarFrame frame{&waveforms, &returns, seconds, threads};
    for (const std::string& f :
         writeLidarFiles(frameConfig, frame, folder.staging() / name, progress)) {
      summary.files.push_back(name + "/" + f);
    }
    frames.push_back(
        {{"index", k}, {"time_s", t}, {"seed", frameConfig.render.seed}, {"folder", name}});
  }
  const json doc = {{"frames", frames},
                    {"count", seq.times_s.size()},
                    {"rotation_rate_Hz", lidar.rotation_rate_Hz},
                    {"doc", "frame k: the lidar's turn from time_s, azimuth column a fired at "
                            "time_s + (azimuth_a - azimuth_start) / 360 / rotation_rate_Hz "
                            "against the scene there (the points' time_offset)"},
                    {"animation_start_s", animated.start_s()},
                    {"animation_end_s", animated.end_s()}};
  writeFileAtomically(folder.staging() / "sequence.json", doc.dump(2) + "\n");
  summary.files.push_back("sequence.json");
  writeFileAtomically(folder.staging() / "config.effective.yaml",
                      config::effectiveConfigYaml(config));
  summary.files.push_back("config.effective.yaml");
  if (options.batchManifest) {
    writeManifest(folder.staging(), options.batchManifest->runName, summary.files,
                  options.batchManifest->inputs);
    summary.files.push_back(kManifestName);
  }
  summary.backend = "cpu";
  summary.device = "CPU (" + std::to_string(threads) + " threads, Embree)";
  throwIfInterrupted();
  commitOutput(folder, progress);
  return summary;
}

}  // namespace tofsim::pipeline
