#pragma once
// Private to the config module: the text of the numeric tables a config
// names (IrfFile.cpp's two-column IRF, SpadTableFile.cpp's one-column DNL),
// read alike: cells trimmed of blanks, a cell a number only when all of it
// is one and finite, file types by their lower-case extension.

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace tofsim::config {

/// s without leading and trailing spaces, tabs and carriage returns.
inline std::string trimmedText(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

/// A whole cell (blanks around it aside) as a finite number.
inline bool wholeNumber(const std::string& cell, double& v) {
  const std::string t = trimmedText(cell);
  if (t.empty()) return false;
  char* end = nullptr;
  v = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size() && std::isfinite(v);
}

/// The extension of path, lower case (".npy", ".csv").
inline std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace tofsim::config
