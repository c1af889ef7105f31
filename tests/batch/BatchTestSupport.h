#pragma once
// Shared by the `tofsim batch` end-to-end tests: a batch file in a temp
// folder and the columns of the summary table.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "pipeline/CliRun.h"

namespace tofsim::test {

// The demo shrunk to a fraction of a second per run, no sensors.
inline const char* kTinyRunSet =
    "set:\n"
    "  camera.resolution: [16, 16]\n"
    "  time.bins: 40\n"
    "  render.shadow_map_resolution: 64\n"
    "  render.indirect.rsm_resolution: 4\n"
    "  render.indirect.points_per_vpl: 100\n"
    "  sensors: []\n";

/// Writes <dir>/batch.yaml: `base`, output `out`, then `body` (set/runs/sweep).
inline std::string writeBatchFile(const std::filesystem::path& dir, const std::string& base,
                                  const std::string& body) {
  const std::filesystem::path path = dir / "batch.yaml";
  std::ofstream(path) << "base: " << base << "\noutput: out\n" << body;
  return path.string();
}

/// The rest of `name`'s row after the name, up to the next double space: the
/// status of a run ("done", "skipped", ...) or a dry run's state ("stale
/// (config changed)"). "" when the row is absent.
inline std::string stateOf(const std::string& output, const std::string& name) {
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind(name + " ", 0) != 0) continue;
    const std::size_t start = line.find_first_not_of(' ', name.size());
    if (start == std::string::npos) return "";
    return line.substr(start, line.find("  ", start) - start);
  }
  return "";
}

}  // namespace tofsim::test
