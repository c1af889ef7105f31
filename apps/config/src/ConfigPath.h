#pragma once
// Private to the config module: a file a config names (a SPAD's IRF, DNL
// table or dark count map, a lens calibration, ...), relative to the config
// file's folder, as the absolute, normal path the loaders read and the
// metadata records, checked to be a file.

#include <filesystem>
#include <string>
#include <system_error>

#include "ConfigNode.h"

namespace tofsim::config {

/// `text` as an absolute, normal path: relative to the folder of n's file.
inline std::filesystem::path configRelativePath(const ConfigNode& n, const std::string& text) {
  std::filesystem::path path = text;
  if (path.is_relative()) path = std::filesystem::path(n.file()).parent_path() / path;
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  if (!ec) path = absolute;
  return path.lexically_normal();
}

/// The data file `key` names (a path as configRelativePath reads it), which
/// must be a regular file: a located error saying which it is otherwise
/// ("<what> not found: <path>", "<path> is a folder, not a file"). One place
/// for every file a config names (IRF, DNL, dark count, afterpulse, lens
/// calibration, waveform, maps, tables).
inline std::filesystem::path existingDataFile(const ConfigNode& n, const std::string& key,
                                              const std::string& what = "file") {
  const std::filesystem::path path = configRelativePath(n, n.requireString(key));
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (std::filesystem::is_regular_file(status)) return path;
  if (std::filesystem::is_directory(status)) {
    n.failKey(key, path.string() + " is a folder, not a file (" + what + ")");
  }
  if (std::filesystem::exists(status)) {
    n.failKey(key, path.string() + " is not a regular file (" + what + ")");
  }
  n.failKey(key, what + " not found: " + path.string());
}

}  // namespace tofsim::config
