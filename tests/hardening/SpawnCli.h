#pragma once
// Starts the tofsim CLI as a child process (fork + exec) so a test can send
// it signals or limit its resources, and waits for it. Output goes to a file.

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "pipeline/CliRun.h"  // cliPath: $TOFSIM_TEST_CLI runs another build

namespace tofsim::test {

struct ChildLimits {
  long maxFileBytes = -1;  ///< RLIMIT_FSIZE in the child (-1: unlimited)
};

/// Runs `sh -c "<cliPath()> args > logFile 2>&1"` in a child; returns its pid.
/// With maxFileBytes, the child ignores SIGXFSZ, so writing past the limit
/// fails with EFBIG the way a full disk fails with ENOSPC.
inline pid_t spawnCli(const std::string& args, const std::string& logFile,
                      const ChildLimits& limits = {}) {
  const std::string command = "exec " + cliPath() + " " + args + " > '" + logFile + "' 2>&1";
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (limits.maxFileBytes >= 0) {
      ::signal(SIGXFSZ, SIG_IGN);
      const rlimit limit{static_cast<rlim_t>(limits.maxFileBytes),
                         static_cast<rlim_t>(limits.maxFileBytes)};
      ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

/// Waits for the child; its exit code, or 128 + signal when a signal killed it.
inline int waitCli(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
}

}  // namespace tofsim::test
