#include "SharedRender.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "KeptAcrossRenders.h"
#include "RunRecord.h"
#include "StagedOutput.h"
#include "tofsim/pipeline/Capture.h"
#include "tofsim/pipeline/Manifest.h"
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

std::string sharedRenderObstacle(const config::RunConfig& config) {
  if (config.nlos) return "an NLOS scan";
  if (config.sequence) return "a sequence";
  if (config.rays) return "a rays: imager (its sensors have no camera for point clouds)";
  if (config.output.format != config::OutputFormat::Npy) return "output.format is not npy";
  if (!config.output.transient) return "output.transient is off (no saved volume)";
  if (choosePsfPath(config) != PsfPath::None) return "camera.psf";
  if (sensorBounces(config)) return "a cwtof sensor with multipath_by_order";
  return "";
}

namespace {

// The source's render files as its manifest lists them (path, bytes,
// checksum): all but its sensors' and its effective config.
std::vector<ManifestEntry> renderFiles(const fs::path& source, const std::string& renderKey) {
  std::ifstream in(source / kManifestName);
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError((source / kManifestName).string() + ": " + e.what());
  }
  const auto render = doc.find("render");
  if (render == doc.end() || render->value("key", "") != renderKey) {
    throw InputError((source / kManifestName).string() +
                     ": records another render key (the run was rendered again since)");
  }
  std::vector<ManifestEntry> files;
  for (const auto& f : doc.at("files")) {
    const std::string path = f.at("path").get<std::string>();
    if (path.rfind("sensors/", 0) == 0 || path == "config.effective.yaml") continue;
    files.push_back({path, f.at("bytes").get<std::uintmax_t>(), f.at("fnv1a64").get<std::string>()});
  }
  return files;
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

}  // namespace

RunSummary senseFromSavedRender(const config::RunConfig& config, const fs::path& source,
                                PreparedRenderer& prepared, const RunOptions& options) {
  TOFSIM_CHECK(options.batchManifest.has_value());
  Progress progress("render", options.quiet);
  RunSummary summary;
  summary.outputDirectory =
      options.outputDirectory.empty() ? config.output.directory : options.outputDirectory;
  const std::vector<ManifestEntry> files = renderFiles(source, options.batchManifest->inputs.render);
  StagedFolder folder(summary.outputDirectory, keptAcrossRenders);
  noteLinkedOutput(folder, progress);
  const fs::path& dir = folder.staging();
  progress.message("the render of run '" + options.batchManifest->renderFrom +
                   "' (same render key " + options.batchManifest->inputs.render +
                   "): its files copied, this run's sensors sensed from its volume");
  copyRenderFiles(source, files, dir, summary.files);
  if (!config.sensors.empty()) {
    const std::vector<std::string> components = {"direct"};
    SavedVolumeStream saved(dir, components);
    const std::vector<std::string> sensed =
        runConfiguredSensors(config, saved, components, dir, progress);
    summary.files.insert(summary.files.end(), sensed.begin(), sensed.end());
  }
  // The record as the render writes it, with the camera its job used.
  prepared.prepare(config);
  writeRecord(config, makeRenderJob(config, prepared.scene()), options, dir, summary.files);
  throwIfInterrupted();
  commitOutput(folder, progress);
  return summary;
}

}  // namespace tofsim::pipeline
