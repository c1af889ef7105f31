#pragma once
// The CLI's exit codes for what a command throws, written once for `tofsim`'s
// main and for the runs a `tofsim batch` worker renders (their log.txt reads
// as a `tofsim render` process's would): 130 / 143 interrupted by SIGINT /
// SIGTERM, 1 bad input or environment, with one line on stderr saying why.

#include <functional>

namespace tofsim::pipeline {

/// Runs `body` and returns its code, or the code of what it threw.
int exitCodeOf(const std::function<int()>& body);

}  // namespace tofsim::pipeline
