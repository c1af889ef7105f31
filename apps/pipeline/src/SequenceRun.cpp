#include "SequenceRun.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "RenderStatsJson.h"
#include "SequenceFrame.h"
#include "SequenceMotion.h"
#include "SequenceVideo.h"
#include "Warning.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/Manifest.h"
#include "tofsim/pipeline/OutputFileNames.h"
#include "tofsim/pipeline/RenderCapture.h"
#include "tofsim/pipeline/RunContentKey.h"
#include "tofsim/scene/AnimatedScene.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

uint64_t sequenceFrameSeed(uint64_t seed, std::size_t frame) {
  // Weyl steps of the golden ratio: frame 0 keeps the seed, the others differ.
  return seed + static_cast<uint64_t>(frame) * 0x9E3779B97F4A7C15ull;
}

namespace {

constexpr const char* kFrameRecord = "frame.json";

std::string frameFolder(std::size_t k) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05zu", k);
  return name;
}

json keyJson(const RunContentKey& key) {
  return {{"config", key.config}, {"scene", key.scene}, {"version", key.version}};
}

// Frame times the animations do not cover are an error: a glTF channel
// holds its last key there, so such frames would repeat one pose.
void checkFrameTimes(const config::SequenceConfig& seq, const scene::AnimatedScene& scene,
                     const fs::path& sceneFile) {
  if (!scene.animated()) {
    throw InputError(seq.at, "sequence",
                     "the scene " + sceneFile.filename().string() +
                         " has no animation that moves a mesh or a camera (tofsim info lists "
                         "what it has)");
  }
  const double a = scene.start_s(), b = scene.end_s();
  for (std::size_t k = 0; k < seq.times_s.size(); ++k) {
    const double t = seq.times_s[k];
    if (t < a || t > b) {
      const auto seconds = [](double s) {
        char text[32];
        std::snprintf(text, sizeof text, "%.6g", s);
        return std::string(text);
      };
      throw InputError(seq.at, seq.rate_Hz > 0.0 ? "sequence.count" : "sequence.times",
                       "frame " + std::to_string(k) + " at " + seconds(t) +
                           " s is outside the scene's animations, [" + seconds(a) + ", " +
                           seconds(b) + "] s");
    }
  }
}

// A frame folder that an earlier run of the same inputs completed.
bool frameDone(const fs::path& folder, std::size_t k, double t, uint64_t seed, const json& key) {
  std::ifstream in(folder / kFrameRecord);
  if (!in) return false;
  try {
    const json doc = json::parse(in);
    return doc.at("index") == k && doc.at("time_s") == t && doc.at("seed") == seed &&
           doc.at("run_key") == key;
  } catch (const json::exception&) {
    return false;  // unreadable: rendered again
  }
}

// (F, H, W) of the frames' depth.npy.
void writeDepthSequence(const fs::path& root, std::size_t frames) {
  std::vector<float> all;
  io::NpyShape frameShape;
  for (std::size_t k = 0; k < frames; ++k) {
    const io::NpyArray depth = io::readNpy(root / frameFolder(k) / files::kDepthNpy);
    if (k == 0) frameShape = depth.shape;
    TOFSIM_CHECK(depth.shape == frameShape);
    all.insert(all.end(), depth.data.begin(), depth.data.end());
  }
  io::NpyShape shape{frames};
  shape.insert(shape.end(), frameShape.begin(), frameShape.end());
  const fs::path tmp = root / ".depth_sequence.tmp.npy";
  io::writeNpy(tmp, shape, all.data());
  fs::rename(tmp, root / "depth_sequence.npy");
}

}  // namespace

RunSummary runSequenceRender(const config::RunConfig& config, const RunOptions& options) {
  const config::SequenceConfig& seq = *config.sequence;
  const RepeatedWarningsOnce once;  // each frame would repeat the same warnings
  Progress progress("sequence", options.quiet);
  scene::LoadReport report;
  const scene::AnimatedScene animated = scene::AnimatedScene::load(config.scene_file, &report);
  reportLoad(report, progress, true);
  checkFrameTimes(seq, animated, config.scene_file);

  RunSummary summary;
  summary.outputDirectory =
      options.outputDirectory.empty() ? config.output.directory : options.outputDirectory;
  const fs::path& root = summary.outputDirectory;
  fs::create_directories(root);
  const RunContentKey runKey =
      options.batchManifest ? options.batchManifest->inputs : runContentKey(config);
  const json key = keyJson(runKey);

  // Prepared once: the renderer (its device, the scene's buffers and BVH,
  // re-prepared in place per frame) and the scene, whose moving meshes and
  // cameras alone are re-baked at each time.
  const RendererChoice renderer = makeRenderer(config, options.eglPlatform);
  progress.message("device: " + renderer.renderer->description() + " (backend " + renderer.backend +
                   ")");
  scene::Scene scene = animated.restScene();
  json frames = json::array();
  std::size_t rendered = 0;
  for (std::size_t k = 0; k < seq.times_s.size(); ++k) {
    throwIfInterrupted();
    const double t = seq.times_s[k];
    config::RunConfig frameConfig = config;
    frameConfig.render.seed = sequenceFrameSeed(config.render.seed, k);
    const std::string folder = frameFolder(k);
    frames.push_back(
        {{"index", k}, {"time_s", t}, {"seed", frameConfig.render.seed}, {"folder", folder}});
    if (frameDone(root / folder, k, t, frameConfig.render.seed, key)) {
      progress.message("frame " + std::to_string(k) + " (t = " + std::to_string(t) +
                       " s): kept from an earlier run of the same inputs");
      continue;
    }
    progress.message("frame " + std::to_string(k + 1) + "/" + std::to_string(seq.times_s.size()) +
                     " at t = " + std::to_string(t) + " s");
    SequenceFrame frame;
    frame.renderer = &renderer;
    frame.jobAt = [&](double offset_s) {
      animated.updateScene(scene, t + offset_s);
      renderer.renderer->sceneChanged();
      return prepareCapture(frameConfig, scene);
    };
    const bool withMotion = config.output.depth && k + 1 < seq.times_s.size();
    const Clock::time_point started = Clock::now();
    frame.record = [&](const fs::path& dir, std::vector<std::string>& written,
                       const capture::RenderResult& result) {
      json doc = {{"index", k}, {"time_s", t}, {"seed", frameConfig.render.seed}, {"run_key", key}};
      if (withMotion) {
        const double next = seq.times_s[k + 1];
        writeMotionFields(dir, motionFields(frameConfig, animated, scene, t, next), written);
        doc["motion_to_time_s"] = next;  // scene_flow.npy, optical_flow.npy: to frame k + 1
      }
      // The frame's cost: every render of it (the sensors' sample times
      // too), its sensors and files; and its render at t_k's own stats.
      doc["seconds"] = std::chrono::duration<double>(Clock::now() - started).count();
      doc["render_stats"] = renderStatsJson(result);
      doc["files"] = written;
      writeFileAtomically(dir / kFrameRecord, doc.dump(2) + "\n");
      written.push_back(kFrameRecord);
    };
    RunOptions frameOptions = options;
    frameOptions.outputDirectory = root / folder;
    frameOptions.batchManifest.reset();
    RunSummary one = renderSequenceFrame(frameConfig, scene, frameOptions, progress, frame);
    summary.backend = one.backend;
    summary.device = one.device;
    summary.result = std::move(one.result);
    ++rendered;
  }
  progress.message(std::to_string(rendered) + " frame(s) rendered, " +
                   std::to_string(seq.times_s.size() - rendered) + " kept");

  // The sequence's own files, each written whole.
  for (std::size_t k = 0; k < seq.times_s.size(); ++k) {
    for (const std::string& f : json::parse(std::ifstream(root / frameFolder(k) / kFrameRecord))
                                    .at("files")
                                    .get<std::vector<std::string>>()) {
      summary.files.push_back(frameFolder(k) + "/" + f);
    }
    summary.files.push_back(frameFolder(k) + "/" + kFrameRecord);
  }
  if (config.output.depth) {
    writeDepthSequence(root, seq.times_s.size());
    summary.files.push_back("depth_sequence.npy");
  }
  if (seq.video && config.output.steady) {
    std::vector<fs::path> steady;
    for (std::size_t k = 0; k < seq.times_s.size(); ++k) {
      steady.push_back(root / frameFolder(k) / files::kSteadyExr);
    }
    writeSequenceVideo(root / "sequence.mp4", config.output, steady, seq.times_s, progress);
    summary.files.push_back("sequence.mp4");
  }
  const json doc = {{"frames", frames},
                    {"count", seq.times_s.size()},
                    {"exposure_samples", seq.exposure_samples},
                    {"animation_start_s", animated.start_s()},
                    {"animation_end_s", animated.end_s()},
                    {"run_key", key}};
  writeFileAtomically(root / "sequence.json", doc.dump(2) + "\n");
  summary.files.push_back("sequence.json");
  writeFileAtomically(root / "config.effective.yaml", config::effectiveConfigYaml(config));
  summary.files.push_back("config.effective.yaml");
  if (options.batchManifest) {
    writeManifest(root, options.batchManifest->runName, summary.files,
                  options.batchManifest->inputs);
    summary.files.push_back(kManifestName);
  }
  return summary;
}

}  // namespace tofsim::pipeline
