#include "SharedRender.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <vector>

#include "RunFolder.h"
#include "RunRecord.h"
#include "tofsim/pipeline/Capture.h"
#include "tofsim/pipeline/Manifest.h"
#include "tofsim/pipeline/OutputEstimate.h"
#include "tofsim/pipeline/OutputFileNames.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/PsfPath.h"
#include "tofsim/pipeline/SavedVolume.h"
#include "tofsim/pipeline/SenseRun.h"
#include "tofsim/pipeline/SensorStreams.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Hash.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;

namespace {
constexpr const char* kSharedVolumesPrefix = ".shared-volumes-";
}  // namespace

std::string sharedRenderObstacle(const config::RunConfig& config) {
  if (config.nlos) return "an NLOS scan";
  if (config.sequence) return "a sequence";
  if (config.lidar) return "a lidar";
  if (config.rays) return "a rays: imager (its sensors have no camera for point clouds)";
  if (config.output.format != config::OutputFormat::Npy) return "output.format is not npy";
  if (choosePsfPath(config) == PsfPath::Transient) {
    return "camera.psf on every time bin (the sensors' cwtof_psf_error needs the light before "
           "it, which is not saved)";
  }
  if (sensorBounces(config)) return "a cwtof sensor with multipath_by_order";
  return "";
}

bool sharesThroughTheBatch(const config::RunConfig& config) { return !config.output.transient; }

namespace {

// The source's render files as its manifest lists them (path, bytes,
// checksum): all but its sensors' and its effective config.
std::vector<ManifestEntry> renderFiles(const fs::path& source, const std::string& renderKey) {
  ManifestRecord manifest = readManifest(source);
  if (manifest.renderKey != renderKey) {
    throw InputError((source / kManifestName).string() +
                     ": records another render key (the run was rendered again since)");
  }
  std::erase_if(manifest.files, [](const ManifestEntry& f) {
    return f.path.rfind("sensors/", 0) == 0 || f.path == "config.effective.yaml";
  });
  return manifest.files;
}

// Each file copied into `dir`, checked against the size and checksum listed:
// a source replaced while it was read is an error, not a mixed set.
void copyRenderFiles(const fs::path& source, const std::vector<ManifestEntry>& files,
                     const fs::path& dir, std::vector<std::string>& written) {
  for (const ManifestEntry& f : files) {
    throwIfInterrupted();
    const fs::path to = dir / f.path;
    fs::create_directories(to.parent_path());
    fs::copy_file(source / f.path, to, fs::copy_options::overwrite_existing);
    if (fs::file_size(to) != f.bytes || hex64(fnv1a64File(to)) != f.fnv1a64) {
      throw InputError((source / f.path).string() +
                       ": differs from its manifest (the run was rendered again while copied)");
    }
    written.push_back(f.path);
  }
}

// The folders of batches that ended without removing theirs (SIGKILL): the
// process named in the folder's name is gone.
void removeDeadBatchesVolumes(const fs::path& outputRoot) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(outputRoot, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(kSharedVolumesPrefix, 0) != 0) continue;
    const long pid = std::strtol(name.c_str() + std::strlen(kSharedVolumesPrefix), nullptr, 10);
    if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
      fs::remove_all(e.path(), ec);
    }
  }
}

// The volume saved for the batch (SharedVolumes) beside the copied render
// files while the sensors read it: hard links where the file system allows.
class LinkedVolume {
 public:
  LinkedVolume(const fs::path& from, const fs::path& dir) {
    for (const std::string_view name : {files::kTransient, files::kMetadata}) {
      const fs::path to = dir / name;
      std::error_code ec;
      fs::create_hard_link(from / name, to, ec);
      if (ec) fs::copy_file(from / name, to);
      linked_.push_back(to);
    }
  }
  ~LinkedVolume() {
    std::error_code ec;
    for (const fs::path& f : linked_) fs::remove(f, ec);
  }
  LinkedVolume(const LinkedVolume&) = delete;
  LinkedVolume& operator=(const LinkedVolume&) = delete;

 private:
  std::vector<fs::path> linked_;
};

}  // namespace

RunSummary senseFromSavedRender(const config::RunConfig& config, const fs::path& source,
                                PreparedRenderer& prepared, const RunOptions& options) {
  TOFSIM_CHECK(options.batchManifest.has_value());
  Progress progress("render", options.quiet);
  const std::vector<ManifestEntry> files = renderFiles(source, options.batchManifest->inputs.render);
  RunFolder folder(config, options, estimateOutputs(config), progress);
  RunSummary summary;
  summary.outputDirectory = folder.path();
  const fs::path& dir = folder.staging();
  progress.message("the render of run '" + options.batchManifest->renderFrom +
                   "' (same render key " + options.batchManifest->inputs.render +
                   "): its files copied, this run's sensors sensed from its volume");
  copyRenderFiles(source, files, dir, summary.files);
  if (!config.sensors.empty()) {
    std::optional<LinkedVolume> linked;
    if (!options.sharedVolume.empty()) linked.emplace(options.sharedVolume, dir);
    const std::vector<std::string> components = {"direct"};
    SavedVolumeStream saved(dir, components);
    const std::vector<std::string> sensed =
        runConfiguredSensors(config, saved, components, dir, progress, choosePsfPath(config));
    summary.files.insert(summary.files.end(), sensed.begin(), sensed.end());
  }
  // The record as the render writes it, with the camera its job used.
  prepared.prepare(config);
  writeRecord(config, makeRenderJob(config, prepared.scene()), options, dir, summary.files);
  folder.commit();
  return summary;
}

SharedVolumes::SharedVolumes(const fs::path& outputRoot, const std::vector<RunContentKey>& keys,
                             const std::vector<bool>& throughTheBatch,
                             const std::deque<std::size_t>& pending)
    : folders_(keys.size()) {
  std::map<std::string, std::size_t> runsOfKey;
  for (const std::size_t run : pending) {
    if (throughTheBatch[run]) ++runsOfKey[keys[run].render];
  }
  removeDeadBatchesVolumes(outputRoot);
  root_ = outputRoot / (std::string(kSharedVolumesPrefix) + std::to_string(::getpid()));
  for (const std::size_t run : pending) {
    if (throughTheBatch[run] && runsOfKey[keys[run].render] > 1) {
      folders_[run] = root_ / keys[run].render;
    }
  }
}

SharedVolumes::~SharedVolumes() {
  std::error_code ec;
  fs::remove_all(root_, ec);
}

}  // namespace tofsim::pipeline
