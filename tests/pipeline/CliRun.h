#pragma once
// Runs the tofsim CLI in a shell and captures its exit code and output, for
// the end-to-end tests.

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace tofsim::test {

struct CommandResult {
  int exitCode;
  std::string output;  ///< stdout and stderr together
};

/// The binary under test: TOFSIM_CLI, or $TOFSIM_TEST_CLI when set (to run
/// an end-to-end test against another build, e.g. to reproduce a bug on an
/// older one).
inline std::string cliPath() {
  const char* other = std::getenv("TOFSIM_TEST_CLI");
  return other && *other ? other : TOFSIM_CLI;
}

inline CommandResult runCli(const std::string& args) {
  const std::string command = cliPath() + " " + args + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  std::string output;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = ::pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

inline std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The shipped demo config.
inline const std::string kCornellConfig =
    std::string(TOFSIM_SOURCE_DIR) + "/configs/cornell_box.yaml";

}  // namespace tofsim::test
