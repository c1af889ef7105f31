#pragma once
// Reads one number of a run's transient.json ("key": value) for the
// end-to-end tests, which need no JSON library for it.

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "pipeline/CliRun.h"

namespace tofsim::test {

/// The number after "key": in the file; NaN when the key is missing.
inline double jsonNumber(const std::filesystem::path& file, const std::string& key) {
  const std::string text = fileBytes(file.string());
  const std::size_t at = text.find("\"" + key + "\":");
  if (at == std::string::npos) return std::nan("");
  return std::strtod(text.c_str() + at + key.size() + 3, nullptr);
}

/// Light off the render's time axis as a fraction of the total.
inline double offAxisFraction(const std::filesystem::path& transientJson) {
  return jsonNumber(transientJson, "fraction_before_axis") +
         jsonNumber(transientJson, "fraction_after_axis");
}

}  // namespace tofsim::test
