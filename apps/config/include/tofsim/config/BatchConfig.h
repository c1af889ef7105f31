#pragma once
// A batch file (`tofsim batch BATCH.yaml`): a base config plus parameter
// sweeps and explicit runs, expanded into a flat, deterministic list of runs,
// each a name and the --set overrides that turn the base config into it.
// Format and expansion order: configs/README.md, "Batch files".

#include <cstddef>
#include <filesystem>
#include <functional>
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

/// One axis of a sweep: one `product:` key, or the `zip:` keys advanced
/// together.
struct SweepAxis {
  std::vector<std::string> keys;
  std::vector<std::vector<std::string>> values;  ///< values[position][key]
};

/// The most runs a batch may have, the sweep's and `runs:` together: each
/// run's config is loaded to validate the batch before anything renders, and
/// each has a row in the summary, a folder and a lock.
inline constexpr std::size_t kMaxBatchRuns = 100000;
/// The longest run name (a folder name; sweep names are cut to it).
inline constexpr std::size_t kMaxRunName = 80;

/// A batch, expanded lazily: its runs are made on demand by run(i) and counted
/// by runCount() without being made, so a large sweep costs nothing until
/// its runs are visited.
struct BatchConfig {
  std::filesystem::path batch_file;
  std::filesystem::path base_config;  ///< resolved against the batch file's folder
  std::filesystem::path output_root;  ///< resolved against the batch file's folder
  std::vector<Override> common;       ///< `set:`, first in every run
  std::vector<Override> extra;        ///< the CLI's --set, last in every run
  std::vector<SweepAxis> sweep;       ///< `product:` keys in file order, then the zip group
  std::size_t sweepRuns = 0;          ///< the product of the axes' lengths; 0 without a sweep
  std::vector<BatchRun> listed;       ///< `runs:` (name, index and varied; overrides by run())

  /// Runs in expansion order: the sweep's, then `runs:`; or the one base run.
  std::size_t runCount() const;
  /// Run `index` (< runCount()), made from the axes: O(number of axes).
  BatchRun run(std::size_t index) const;
};

/// Reads a batch file. `extra` overrides (the CLI's --set) are appended to
/// every run, after the batch file's own. Unknown keys, zip lists of unequal
/// length, empty lists, a sweep of more than kMaxBatchRuns runs, run names
/// that are not plain folder names (letters, digits, `_-.,+`, no leading
/// '.', at most kMaxRunName characters) or used twice, and an `output:` that
/// is a file are located errors.
/// The run configs themselves are not validated here (see validateBatch).
BatchConfig loadBatchConfig(const std::filesystem::path& file,
                            const std::vector<Override>& extra = {});

/// Loads every run's config (base + overrides) so that a bad value stops the
/// batch before anything renders. Throws one InputError naming the failing
/// runs (the first few with their located errors, and how many). `progress`
/// is called with (runs checked, runs) after each run; it may throw (an
/// interrupt).
void validateBatch(const BatchConfig& batch,
                   const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace tofsim::config
