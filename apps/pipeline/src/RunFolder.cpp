#include "RunFolder.h"

#include "KeptAcrossRenders.h"
#include "RunRecord.h"
#include "StagedOutput.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

RunFolder::RunFolder(const config::RunConfig& config, const RunOptions& options,
                     const OutputEstimate& outputs, const Progress& progress)
    : path_(options.outputDirectory.empty() ? config.output.directory : options.outputDirectory),
      folder_(path_, keptAcrossRenders),
      progress_(progress) {
  noteLinkedOutput(folder_, progress);
  checkOutputsFit(outputs, config, folder_.staging());
}

void RunFolder::commit() {
  throwIfInterrupted();
  commitOutput(folder_, progress_);
}

void RunFolder::finish(const config::RunConfig& config, const RunOptions& options,
                       std::vector<std::string>& files) {
  writeRecord(config, options, folder_.staging(), files);
  commit();
}

}  // namespace tofsim::pipeline
