#include "RunRecord.h"

#include "tofsim/capture/Imager.h"
#include "tofsim/pipeline/Manifest.h"
#include "tofsim/util/AtomicFile.h"

namespace tofsim::pipeline {

void writeRecord(const config::RunConfig& config, const RunOptions& options,
                 const std::filesystem::path& dir, std::vector<std::string>& files) {
  writeFileAtomically(dir / "config.effective.yaml", config::effectiveConfigYaml(config));
  files.push_back("config.effective.yaml");
  if (options.batchManifest) {
    // Last: it lists the files above with their checksums, so it exists
    // only once all of them do.
    writeManifest(dir, options.batchManifest->runName, files, options.batchManifest->inputs,
                  options.batchManifest->renderFrom);
    files.push_back(kManifestName);
  }
}

void writeRecord(const config::RunConfig& config, const capture::RenderJob& job,
                 const RunOptions& options, const std::filesystem::path& dir,
                 std::vector<std::string>& files) {
  // What was used: a glTF camera's position, view and field of view, not the
  // config's defaults, so the file reproduces the run without the glTF camera too.
  config::RunConfig used = config;
  if (const capture::Camera* camera = capture::cameraOf(job.imager)) used.camera.camera = *camera;
  writeRecord(used, options, dir, files);
}

}  // namespace tofsim::pipeline
