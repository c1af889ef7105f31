#pragma once
// manifest.json: the proof that a batch run finished. Written last and
// atomically, it lists every output file under the run folder with its size
// and FNV-1a 64 checksum. A run is complete iff its manifest exists, parses
// and every listed file exists with the listed size (and, when verifying,
// the listed checksum). A run killed at any moment therefore never looks
// complete: its manifest is either absent or describes files already whole.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tofsim::pipeline {

inline constexpr const char* kManifestName = "manifest.json";
/// The child's stdout/stderr; not an output, so not in the manifest.
inline constexpr const char* kRunLogName = "log.txt";

struct ManifestEntry {
  std::string path;  ///< relative to the run folder, '/' separated
  std::uintmax_t bytes = 0;
  std::string fnv1a64;  ///< 16 hex digits
};

/// Lists every regular file under `directory` (except the manifest and the
/// log), hashes it and writes manifest.json atomically. Returns the entries.
std::vector<ManifestEntry> writeManifest(const std::filesystem::path& directory,
                                         const std::string& runName);

/// True when `directory` holds a complete run (see above). `why` (optional)
/// receives the reason when it does not.
bool runIsComplete(const std::filesystem::path& directory, bool verifyChecksums,
                   std::string* why = nullptr);

}  // namespace tofsim::pipeline
