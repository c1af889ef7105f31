#pragma once
// `tofsim batch`: runs the expanded runs of a batch file (BatchConfig.h),
// each in its own folder <output>/<run name>/, skipping runs that are done
// for their current content key (Manifest.h, RunContentKey.h) and redoing
// missing, stale and incomplete ones.
//
// The runs render on `jobs` worker processes forked from the batch
// (BatchWorker.h), each keeping its scene and renderer loaded across the
// runs it is given (PreparedRenderer.h), each run rendered as `tofsim render
// <base config> --set ... -o <run dir> --batch-run <name>` renders it (the
// same files, byte for byte), its stdout and stderr in <run dir>/log.txt;
// the render writes the run's manifest last. The batch holds <output>/.<run
// name>.lock (flock) while a run is going, and hands it to the worker, so
// two batches over one output tree never run the same run at once: the
// second reports it `busy`. SIGINT/SIGTERM: no new run starts, the signal
// goes on to the busy workers, the batch waits for them and returns a
// summary with `interruptSignal` set. A worker that crashes takes only its
// run down: the batch counts its exit status and starts another worker.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/config/BatchConfig.h"

namespace tofsim::pipeline {

/// The most runs at once (--jobs): each on a worker process with its own
/// render buffers (and GL context).
inline constexpr int kMaxJobs = 256;

struct BatchOptions {
  std::filesystem::path batchFile;
  std::vector<config::Override> overrides;  ///< the CLI's --set, after the batch's own
  int jobs = 1;                             ///< worker processes, 1 .. kMaxJobs
  int shardIndex = 1;                       ///< K of --shard K/N, 1-based
  int shardCount = 1;                       ///< N of --shard K/N
  bool dryRun = false;                      ///< list the runs, render nothing
  bool verify = false;                      ///< check checksums, not only sizes, to skip
  bool quiet = false;
};

enum class BatchRunStatus { Done, Skipped, Failed, Pending, Interrupted, Busy };
/// "done", "skipped", "failed", "pending", "interrupted", "busy".
const char* batchRunStatusName(BatchRunStatus status);

struct BatchRunResult {
  std::size_t index = 0;
  std::string name;
  std::filesystem::path directory;
  BatchRunStatus status = BatchRunStatus::Pending;
  double seconds = 0.0;
  std::string state;  ///< before the batch: assessRun's text ("done", "stale (...)", ...)
  std::string
      message;  ///< failed: the last line of log.txt; busy: the holder; dry run: the overrides
};

struct BatchSummary {
  std::size_t totalRuns = 0;         ///< in the whole batch, all shards
  std::vector<BatchRunResult> runs;  ///< this shard's, in expansion order
  int interruptSignal = 0;           ///< SIGINT / SIGTERM that stopped the batch, or 0
  bool anyFailed() const;
  /// 128 + signal when interrupted; else 1 when a run failed or was busy; else 0.
  int exitCode() const;
};

/// Parses "K/N" (1 <= K <= N); throws InputError otherwise.
void parseShard(const std::string& text, int& index, int& count);

/// Run i (0-based expansion index) belongs to shard K of N iff i % N == K - 1.
bool inShard(std::size_t index, int shardIndex, int shardCount);

/// Loads and validates the batch (every run's config, before anything runs),
/// then runs this shard's runs that are not done. Throws InputError for a bad
/// batch file or an invalid run config; a run that fails while running is
/// reported in the summary, and the others still run. An interrupt while runs
/// render is not an exception here: the summary says which runs it stopped;
/// one during the passes over every run before that (their configs, content
/// keys and folders' states, with progress from 1000 runs on) throws
/// tofsim::Interrupted, as nothing has started; a dry run interrupted after
/// its last pass returns its summary with interruptSignal set.
BatchSummary runBatch(const BatchOptions& options);

/// The table printed at the end: run, status, seconds, output folder; for a
/// dry run: run, state, varied keys.
std::string formatBatchSummary(const BatchSummary& summary, bool dryRun);

}  // namespace tofsim::pipeline
