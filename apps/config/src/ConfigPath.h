#pragma once
// Private to the config module: a file a config names (a SPAD's IRF, DNL
// table or dark count map), relative to the config file's folder, as the
// absolute, normal path the loaders read and the metadata records.

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

}  // namespace tofsim::config
