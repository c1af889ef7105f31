#pragma once
// `tofsim batch`: runs the expanded runs of a batch file (BatchConfig.h),
// each in its own folder <output>/<run name>/, skipping complete runs
// (Manifest.h) and redoing incomplete ones.
//
// Each run is a child process: the tofsim executable itself, as
// `tofsim render <base config> --set ... -o <run dir>`, its stdout and stderr
// in <run dir>/log.txt. Processes rather than threads because every render
// owns a GL context and large buffers, and because a crash (or a driver
// abort) in one run must not take the batch down: the parent only counts
// exit codes. `jobs` children run at once.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/config/BatchConfig.h"

namespace tofsim::pipeline {

struct BatchOptions {
  std::filesystem::path batchFile;
  std::vector<config::Override> overrides;  ///< the CLI's --set, after the batch's own
  int jobs = 1;                             ///< child processes at once, >= 1
  int shardIndex = 1;                       ///< K of --shard K/N, 1-based
  int shardCount = 1;                       ///< N of --shard K/N
  bool dryRun = false;                      ///< list the runs, render nothing
  bool verify = false;                      ///< check checksums, not only sizes, to skip
  bool quiet = false;
  std::filesystem::path executable = "/proc/self/exe";  ///< the tofsim binary to run
};

enum class BatchRunStatus { Done, Skipped, Failed, Pending };

struct BatchRunResult {
  std::size_t index = 0;
  std::string name;
  std::filesystem::path directory;
  BatchRunStatus status = BatchRunStatus::Pending;
  double seconds = 0.0;
  std::string message;  ///< failed: the last line of log.txt; dry run: the overrides
};

struct BatchSummary {
  std::size_t totalRuns = 0;         ///< in the whole batch, all shards
  std::vector<BatchRunResult> runs;  ///< this shard's, in expansion order
  bool anyFailed() const;
};

/// Parses "K/N" (1 <= K <= N); throws InputError otherwise.
void parseShard(const std::string& text, int& index, int& count);

/// Run i (0-based expansion index) belongs to shard K of N iff i % N == K - 1.
bool inShard(std::size_t index, int shardIndex, int shardCount);

/// Loads and validates the batch (every run's config, before anything runs),
/// then runs this shard's incomplete runs. Throws InputError for a bad batch
/// file or an invalid run config; a run that fails while running is reported
/// in the summary, and the others still run.
BatchSummary runBatch(const BatchOptions& options);

/// The table printed at the end: run, status, seconds, output folder.
std::string formatBatchSummary(const BatchSummary& summary, bool dryRun);

}  // namespace tofsim::pipeline
