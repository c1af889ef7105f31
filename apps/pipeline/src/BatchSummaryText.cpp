// The batch's status names and the table it prints at its end (BatchRun.h).
#include "tofsim/pipeline/BatchRun.h"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <string>

namespace tofsim::pipeline {

const char* batchRunStatusName(BatchRunStatus s) {
  switch (s) {
    case BatchRunStatus::Done:
      return "done";
    case BatchRunStatus::Skipped:
      return "skipped";
    case BatchRunStatus::Failed:
      return "failed";
    case BatchRunStatus::Pending:
      return "pending";
    case BatchRunStatus::Interrupted:
      return "interrupted";
    case BatchRunStatus::Busy:
      return "busy";
  }
  return "?";
}

std::string formatBatchSummary(const BatchSummary& summary, bool dryRun) {
  std::size_t width = 3, statusWidth = std::string("interrupted").size();
  for (const BatchRunResult& r : summary.runs) {
    width = std::max(width, r.name.size());
    if (dryRun) statusWidth = std::max(statusWidth, r.state.size());
  }
  std::string out;
  char line[2048];
  const int w = static_cast<int>(width), sw = static_cast<int>(statusWidth);
  if (dryRun) {
    std::snprintf(line, sizeof line, "%-*s  %-*s  %s\n", w, "run", sw, "state", "varied keys");
  } else {
    std::snprintf(line, sizeof line, "%-*s  %-*s  %8s  %s\n", w, "run", sw, "status", "seconds",
                  "output");
  }
  out += line;
  std::size_t counts[6] = {0, 0, 0, 0, 0, 0};
  for (const BatchRunResult& r : summary.runs) {
    ++counts[static_cast<int>(r.status)];
    if (dryRun) {
      std::snprintf(line, sizeof line, "%-*s  %-*s  %s\n", w, r.name.c_str(), sw, r.state.c_str(),
                    r.message.c_str());
    } else {
      std::snprintf(line, sizeof line, "%-*s  %-*s  %8.1f  %s\n", w, r.name.c_str(), sw,
                    batchRunStatusName(r.status), r.seconds, r.directory.string().c_str());
    }
    out += line;
    if (!dryRun && !r.message.empty()) out += "    " + r.message + "\n";
  }
  if (dryRun) {
    std::snprintf(line, sizeof line,
                  "batch: %zu of %zu run(s) in this shard: %zu done, %zu to run\n",
                  summary.runs.size(), summary.totalRuns, counts[1], counts[3]);
  } else {
    std::snprintf(line, sizeof line,
                  "batch: %zu of %zu run(s) in this shard: %zu done, %zu skipped, %zu failed, "
                  "%zu interrupted, %zu busy, %zu pending\n",
                  summary.runs.size(), summary.totalRuns, counts[0], counts[1], counts[2],
                  counts[4], counts[5], counts[3]);
  }
  out += line;
  if (summary.interruptSignal != 0) {
    out += std::string("batch: interrupted by ") +
           (summary.interruptSignal == SIGINT ? "SIGINT" : "SIGTERM") +
           "; rerun the batch to finish the interrupted and pending runs\n";
  }
  return out;
}

}  // namespace tofsim::pipeline
