#include "SequenceRun.h"

#include <sys/stat.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>

#include "KeptAcrossRenders.h"
#include "RenderStatsJson.h"
#include "SequenceFrame.h"
#include "SequenceMotion.h"
#include "SequenceVideo.h"
#include "StagedOutput.h"
#include "Warning.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/CaptureLoop.h"
#include "tofsim/pipeline/Manifest.h"
#include "tofsim/pipeline/OutputFileNames.h"
#include "tofsim/pipeline/ConfiguredScene.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/pipeline/RenderCapture.h"
#include "tofsim/pipeline/RunContentKey.h"
#include "tofsim/scene/AnimatedScene.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"
#include "tofsim/util/StagedFolder.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

uint64_t sequenceFrameSeed(uint64_t seed, std::size_t frame) {
  // Weyl steps of the golden ratio: frame 0 keeps the seed, the others differ.
  return seed + static_cast<uint64_t>(frame) * 0x9E3779B97F4A7C15ull;
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

namespace {

constexpr const char* kFrameRecord = "frame.json";
// Where this run's frames are rendered, each committed whole as it is done,
// inside the sequence's folder and hidden: the earlier set beside it stays
// complete until the new one swaps in, and a rerun of the same inputs after
// an interrupt resumes from it. The swap carries it away with the earlier set.
constexpr const char* kPartialFolder = ".tofsim-sequence-partial";

std::string frameFolder(std::size_t k) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05zu", k);
  return name;
}

json keyJson(const RunContentKey& key) {
  return {{"config", key.config}, {"scene", key.scene}, {"version", key.version}};
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

// Staging folders that frames' writers left (an abort, kill -9) where
// frames are rendered now and where they were before kPartialFolder: this
// run holds the sequence's lock, so no one is writing them.
void removeDeadFrameStaging(const std::vector<fs::path>& folders, const fs::path& ours) {
  std::error_code ec;
  for (const fs::path& folder : folders) {
    std::vector<fs::path> dead;
    for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
      if (StagedFolder::isStaging(e.path().filename().string()) && e.path() != ours) {
        dead.push_back(e.path());
      }
    }
    for (const fs::path& p : dead) fs::remove_all(p, ec);
  }
}

// kPartialFolder, a folder of this run's making: anything else at that name
// (a link included, never followed) goes.
void makePartialFolder(const fs::path& partial) {
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(partial, ec))) fs::remove(partial, ec);
  if (::mkdir(partial.c_str(), 0777) != 0 && errno != EEXIST) {
    throw InputError(FileLoc{partial.string()}, "",
                     "cannot create the frames' folder: " + std::string(std::strerror(errno)));
  }
}

// On unwinding: the partial folder goes when it holds no finished frame, so
// that a run that made the sequence's folder for nothing leaves nothing.
struct RemoveWhenEmpty {
  fs::path folder;
  ~RemoveWhenEmpty() {
    std::error_code ec;
    fs::remove(folder, ec);  // fails, and so keeps it, when not empty
  }
};

// Frame k's folder of the new set: hard links to where it was rendered or kept.
void linkFrames(const std::vector<fs::path>& frames, const fs::path& staging) {
  try {
    for (std::size_t k = 0; k < frames.size(); ++k) {
      linkTree(frames[k], staging / frameFolder(k));
    }
  } catch (const fs::filesystem_error& e) {
    throw InputError(FileLoc{staging.parent_path().string()}, "",
                     std::string("cannot link the frames into the new set: ") + e.what());
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
  io::writeNpy(root / "depth_sequence.npy", shape, all.data());  // whole or not at all
}

// Frame k as a capture of the loop: its config (its seed), its folder, and
// how the scene moves to its time. Rendered into `fresh` (staged, committed
// whole) by the sequence's renderer, the scene moved in place to each time
// a sensor samples within the frame; its record frame.json written last.
struct FrameCapture {
  config::RunConfig config;
  RunOptions options;
  SequenceFrame frame;
  RunSummary summary;
  Clock::time_point started = Clock::now();
};

void setUpFrame(FrameCapture& f, std::size_t k, const scene::AnimatedScene& animated,
                scene::Scene& scene, PreparedRenderer& prepared, const RendererChoice& renderer,
                const json& key, const fs::path& fresh) {
  const std::vector<double>& times = f.config.sequence->times_s;
  const double t = times[k];
  f.frame.prepared = &prepared;
  f.frame.jobAt = [&f, &animated, &scene, &renderer, t](double offset_s) {
    animated.updateScene(scene, t + offset_s);
    renderer.renderer->sceneChanged();
    return prepareCapture(f.config, scene);
  };
  const bool withMotion = f.config.output.depth && k + 1 < times.size();
  f.frame.record = [&f, &animated, &scene, &times, key, k, t, withMotion](
                       const fs::path& dir, std::vector<std::string>& written,
                       const capture::RenderResult& result) {
    json doc = {{"index", k}, {"time_s", t}, {"seed", f.config.render.seed}, {"run_key", key}};
    if (withMotion) {
      const double next = times[k + 1];
      writeMotionFields(dir, motionFields(f.config, animated, scene, t, next), written);
      doc["motion_to_time_s"] = next;  // scene_flow.npy, optical_flow.npy: to frame k + 1
    }
    // The frame's cost: every render of it (the sensors' sample times
    // too), its sensors and files; and its render at t_k's own stats.
    doc["seconds"] = std::chrono::duration<double>(Clock::now() - f.started).count();
    doc["render_stats"] = renderStatsJson(result);
    doc["files"] = written;
    writeFileAtomically(dir / kFrameRecord, doc.dump(2) + "\n");
    written.push_back(kFrameRecord);
  };
  f.options.outputDirectory = fresh;
  f.options.batchManifest.reset();
}

// The frames of the new set: their entries of sequence.json, each one's
// finished folder (kept from an earlier run of the same inputs, or the one
// it is rendered into) and which are to be rendered.
struct FramePlan {
  json frames = json::array();
  std::vector<fs::path> done;
  std::vector<std::size_t> fresh;
};

FramePlan planFrames(const config::RunConfig& config, const fs::path& root, const fs::path& partial,
                     const json& key, const Progress& progress) {
  const std::vector<double>& times = config.sequence->times_s;
  FramePlan plan;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    const uint64_t seed = sequenceFrameSeed(config.render.seed, k);
    const std::string name = frameFolder(k);
    plan.frames.push_back({{"index", k}, {"time_s", t}, {"seed", seed}, {"folder", name}});
    // Finished by an interrupted run, or in the earlier complete set.
    std::optional<fs::path> kept;
    for (const fs::path& f : {partial / name, root / name}) {
      if (!kept && frameDone(f, k, t, seed, key)) kept = f;
    }
    plan.done.push_back(kept.value_or(partial / name));
    if (kept) {
      progress.message("frame " + std::to_string(k) + " (t = " + std::to_string(t) +
                       " s): kept from an earlier run of the same inputs");
    } else {
      plan.fresh.push_back(k);
    }
  }
  return plan;
}

// The frames to render, each a capture of the loop, one after another (the
// scene moves in place; the frame in flight is `current`), through the
// renderer prepared once: its device, the scene's buffers and BVH,
// re-prepared in place per frame, and the scene, whose moving meshes and
// cameras alone are re-baked at each time. `summary`: the last frame's render.
void renderFrames(const config::RunConfig& config, const FramePlan& plan,
                  const scene::AnimatedScene& animated, const scene::LoadReport& report,
                  PreparedRenderer& prepared, const json& key, const RunOptions& options,
                  Progress& progress, RunSummary& summary) {
  const std::vector<double>& times = config.sequence->times_s;
  const RendererChoice& renderer = prepared.renderer(config);
  progress.message("device: " + renderer.renderer->description() + " (backend " + renderer.backend +
                   ")");
  scene::Scene scene = animated.restScene();
  configureScene(config, scene, report);  // checked before anything was written (runSequenceRender)
  std::optional<FrameCapture> current;
  CaptureLoopOptions loop;
  loop.withinCapture = [&](std::size_t d, std::size_t total, const std::string& what) {
    progress.update(d, total, what);
  };
  renderCaptures(
      prepared, config, plan.fresh.size(),
      [&](std::size_t i) {
        const std::size_t k = plan.fresh[i];
        progress.message("frame " + std::to_string(k + 1) + "/" + std::to_string(times.size()) +
                         " at t = " + std::to_string(times[k]) + " s");
        current.reset();
        current.emplace(FrameCapture{config, options, {}, {}});
        current->config.render.seed = sequenceFrameSeed(config.render.seed, k);
        setUpFrame(*current, k, animated, scene, prepared, renderer, key, plan.done[k]);
        return current->frame.jobAt(0.0);
      },
      [&](std::size_t, const capture::RenderJob& job) {
        FrameCapture& f = *current;
        return outputSink(f.config, job, f.options, progress, f.summary, &f.frame);
      },
      loop);
  if (current) {
    summary.backend = current->summary.backend;
    summary.device = current->summary.device;
    summary.result = std::move(current->summary.result);
  }
  progress.message(std::to_string(plan.fresh.size()) + " frame(s) rendered, " +
                   std::to_string(times.size() - plan.fresh.size()) + " kept");
}

// The sequence's own files beside its frames (linked into `staging`): every
// frame's files listed, depth_sequence.npy, sequence.mp4, sequence.json, the
// effective config and, for a batch's run, the manifest.
void writeSequenceFiles(const config::RunConfig& config, const scene::AnimatedScene& animated,
                        const json& frames, const json& key, const fs::path& staging,
                        const RunOptions& options, Progress& progress, RunSummary& summary) {
  const config::SequenceConfig& seq = *config.sequence;
  for (std::size_t k = 0; k < seq.times_s.size(); ++k) {
    for (const std::string& f : json::parse(std::ifstream(staging / frameFolder(k) / kFrameRecord))
                                    .at("files")
                                    .get<std::vector<std::string>>()) {
      summary.files.push_back(frameFolder(k) + "/" + f);
    }
    summary.files.push_back(frameFolder(k) + "/" + kFrameRecord);
  }
  if (config.output.depth) {
    writeDepthSequence(staging, seq.times_s.size());
    summary.files.push_back("depth_sequence.npy");
  }
  if (seq.video && config.output.steady) {
    std::vector<fs::path> steady;
    for (std::size_t k = 0; k < seq.times_s.size(); ++k) {
      steady.push_back(staging / frameFolder(k) / files::kSteadyExr);
    }
    writeSequenceVideo(staging / "sequence.mp4", config.output, steady, seq.times_s, progress);
    summary.files.push_back("sequence.mp4");
  }
  const json doc = {{"frames", frames},
                    {"count", seq.times_s.size()},
                    {"exposure_samples", seq.exposure_samples},
                    {"animation_start_s", animated.start_s()},
                    {"animation_end_s", animated.end_s()},
                    {"run_key", key}};
  writeFileAtomically(staging / "sequence.json", doc.dump(2) + "\n");
  summary.files.push_back("sequence.json");
  writeFileAtomically(staging / "config.effective.yaml", config::effectiveConfigYaml(config));
  summary.files.push_back("config.effective.yaml");
  if (options.batchManifest) {
    writeManifest(staging, options.batchManifest->runName, summary.files,
                  options.batchManifest->inputs);
    summary.files.push_back(kManifestName);
  }
}

}  // namespace

RunSummary runSequenceRender(const config::RunConfig& config, PreparedRenderer& prepared,
                             const RunOptions& options) {
  const config::SequenceConfig& seq = *config.sequence;
  const RepeatedWarningsOnce once;  // each frame would repeat the same warnings
  Progress progress("sequence", options.quiet);
  scene::LoadReport report;
  const scene::AnimatedScene animated = scene::AnimatedScene::load(config.scene_file, &report);
  reportLoad(report, progress, true);
  checkFrameTimes(seq, animated, config.scene_file);
  {
    // The materials' delays on a copy of the materials alone, so that their
    // errors come before anything is written (renderFrames applies them to
    // its scene).
    scene::Scene materials;
    materials.materials = animated.restScene().materials;
    configureScene(config, materials, report);
  }

  RunSummary summary;
  summary.outputDirectory =
      options.outputDirectory.empty() ? config.output.directory : options.outputDirectory;
  // A sequence is one result: its frames and files are staged and swap in
  // together, so an interrupt or an error leaves the earlier set whole.
  StagedFolder folder(summary.outputDirectory, keptAcrossRenders);
  noteLinkedOutput(folder, progress);
  const fs::path root = folder.folder();
  const fs::path partial = root / kPartialFolder;
  removeDeadFrameStaging({root, partial}, folder.staging());
  makePartialFolder(partial);
  const RemoveWhenEmpty dropUnused{partial};
  const RunContentKey runKey =
      options.batchManifest ? options.batchManifest->inputs : runContentKey(config);
  const json key = keyJson(runKey);

  const FramePlan plan = planFrames(config, root, partial, key, progress);
  renderFrames(config, plan, animated, report, prepared, key, options, progress, summary);

  // The new set: the frames, then the sequence's own files.
  linkFrames(plan.done, folder.staging());
  writeSequenceFiles(config, animated, plan.frames, key, folder.staging(), options, progress,
                     summary);
  // A signal during the last steps still means "stop" (as for one render).
  throwIfInterrupted();
  commitOutput(folder, progress);  // the earlier set, the partial folder with it, goes
  return summary;
}

}  // namespace tofsim::pipeline
