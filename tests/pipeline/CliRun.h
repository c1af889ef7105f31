#pragma once
// Runs the tofsim CLI in a shell and captures its exit code and output, for
// the end-to-end tests.

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

/// Runs the CLI with `args`; `environment` ("NAME=value ...") prefixes the command.
inline CommandResult runCli(const std::string& args, const std::string& environment = "") {
  const std::string command = environment + " " + cliPath() + " " + args + " 2>&1";
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

namespace tofsim::test {

/// The files under `dir` (relative paths, recursive) that a user sees as
/// results: dot entries (the folder's lock, staging folders) are skipped.
inline std::vector<std::string> visibleFiles(const std::filesystem::path& dir) {
  std::vector<std::string> files;
  if (!std::filesystem::exists(dir)) return files;
  for (auto it = std::filesystem::recursive_directory_iterator(dir);
       it != std::filesystem::recursive_directory_iterator(); ++it) {
    if (it->path().filename().string().rfind('.', 0) == 0) {
      if (it->is_directory()) it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file()) {
      files.push_back(std::filesystem::relative(it->path(), dir).generic_string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace tofsim::test
