#pragma once
// Private to the pipeline: the output folder a run writes, set up once for
// camera, lidar and NLOS renders and for a batch run that takes another
// run's render. The folder is -o, else the config's output.directory; the
// new set is staged (StagedFolder: the earlier set stays until the new one
// is whole; an error or an interrupt before commit() removes the staging
// folder), a batch's log.txt is kept (keptAcrossRenders), a link is said,
// and the outputs' sizes are checked against its disk before anything
// renders.

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/OutputEstimate.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/pipeline/RenderRun.h"
#include "tofsim/util/StagedFolder.h"

namespace tofsim::pipeline {

class RunFolder {
 public:
  RunFolder(const config::RunConfig& config, const RunOptions& options,
            const OutputEstimate& outputs, const Progress& progress);

  /// As given (RunSummary::outputDirectory).
  const std::filesystem::path& path() const { return path_; }
  /// Where the run writes its set.
  const std::filesystem::path& staging() const { return folder_.staging(); }

  /// The staged set made the folder's, unless a signal came meanwhile
  /// (the earlier results then stay: throws Interrupted).
  void commit();
  /// Last: the record (RunRecord.h: the effective config and a batch run's
  /// manifest, added to `files`), then commit().
  void finish(const config::RunConfig& config, const RunOptions& options,
              std::vector<std::string>& files);

 private:
  std::filesystem::path path_;
  StagedFolder folder_;
  const Progress& progress_;
};

}  // namespace tofsim::pipeline
