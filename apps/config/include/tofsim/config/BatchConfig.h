#pragma once
// A batch file (`tofsim batch BATCH.yaml`): a base config plus parameter
// sweeps and explicit runs, expanded into a flat, deterministic list of runs,
// each a name and the --set overrides that turn the base config into it.
// Format and expansion order: configs/README.md, "Batch files".

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"

namespace tofsim::config {

struct BatchRun {
  std::size_t index = 0;            ///< position in expansion order (shards use it)
  std::string name;                 ///< unique, filesystem-safe: the run's folder name
  std::vector<Override> overrides;  ///< applied to the base config, in order
  std::vector<Override> varied;     ///< the sweep values alone (for listings)
};

struct BatchConfig {
  std::filesystem::path batch_file;
  std::filesystem::path base_config;  ///< resolved against the batch file's folder
  std::filesystem::path output_root;  ///< resolved against the batch file's folder
  std::vector<BatchRun> runs;         ///< expansion order
};

/// Reads and expands a batch file. `extra` overrides (the CLI's --set) are
/// appended to every run, after the batch file's own. Unknown keys, zip lists
/// of unequal length, empty lists and duplicate run names are located errors.
/// The run configs themselves are not validated here (see validateBatch).
BatchConfig loadBatchConfig(const std::filesystem::path& file,
                            const std::vector<Override>& extra = {});

/// Loads every run's config (base + overrides) so that a bad value stops the
/// batch before anything renders. Throws one InputError naming each failing
/// run with its located error.
void validateBatch(const BatchConfig& batch);

}  // namespace tofsim::config
