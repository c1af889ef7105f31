#pragma once
// manifest.json: the proof that a batch run finished, and of what. The child
// render writes it as the last file of its output set, atomically: it lists
// every output file of the run with its size and FNV-1a 64 checksum, and the
// run's content key (RunContentKey.h) under "inputs". A run is done iff its
// manifest exists, parses, records the key its config has now, and every
// listed file exists with the listed size (and, when verifying, the listed
// checksum). A run killed at any moment therefore never looks done: its
// manifest is either absent or describes files already whole.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/pipeline/RunContentKey.h"

namespace tofsim::pipeline {

inline constexpr const char* kManifestName = "manifest.json";
/// The child's stdout/stderr; not an output, so not in the manifest.
inline constexpr const char* kRunLogName = "log.txt";

struct ManifestEntry {
  std::string path;  ///< relative to the run folder, '/' separated
  std::uintmax_t bytes = 0;
  std::string fnv1a64;  ///< 16 hex digits
};

/// Hashes `files` (relative to `directory`: the outputs a render wrote) and
/// writes manifest.json atomically. The log, the manifest itself and any
/// dot-file (locks, staging folders) are never listed. Returns the entries,
/// sorted by path. `renderFrom`: the run whose render this run's volume
/// and render files are (SharedRender.h; "" for the run itself), recorded
/// with the render key as "render": {"key", "from"}.
std::vector<ManifestEntry> writeManifest(const std::filesystem::path& directory,
                                         const std::string& runName,
                                         const std::vector<std::string>& files,
                                         const RunContentKey& inputs,
                                         const std::string& renderFrom = "");

/// A manifest as read back: what writeManifest wrote.
struct ManifestRecord {
  std::optional<RunContentKey> inputs;  ///< none: a manifest of an older tofsim
  std::string renderKey;                ///< "render": {"key"}; "" when absent
  std::string renderFrom;               ///< "render": {"from"}; "" when absent
  std::vector<ManifestEntry> files;
};

/// The one reader of `directory`'s manifest.json, opened without following a
/// link (io::readFileNoFollow). Throws InputError naming the file when it is
/// missing, a link, or not a manifest.
ManifestRecord readManifest(const std::filesystem::path& directory);

/// Where a run folder stands against the key its config has now.
enum class RunState { Done, Missing, Stale, Incomplete };

struct RunAssessment {
  RunState state = RunState::Missing;
  /// As `--dry-run` prints it: "done", "missing", "stale (config changed)",
  /// "stale (scene changed)", "stale (version changed)", "stale (no inputs
  /// recorded)" or "incomplete (<why>)".
  std::string text;
};

RunAssessment assessRun(const std::filesystem::path& directory, const RunContentKey& expected,
                        bool verifyChecksums);

}  // namespace tofsim::pipeline
