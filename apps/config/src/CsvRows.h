#pragma once
// Private to the config module: the rows of a numeric table file a config
// names (an IRF, a DNL table, a measured waveform, an afterpulse delay
// table), read alike: '#' comments and blank lines skipped, a first row of
// the right width that is not all numbers a header, every other row exactly
// `columns` finite numbers (TableText.h), or a located error at the config's
// key naming the file and its line. What a reader then requires of the
// values is its own, reported at the row's line (failAt).

#include <cstddef>
#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include "ConfigNode.h"

namespace tofsim::config {

struct CsvRow {
  int line = 0;  ///< 1-based, in the file
  std::vector<double> cells;
};

/// `description` names the columns in errors ("time in s, value").
std::vector<CsvRow> readCsvRows(const ConfigNode& n, const std::string& key,
                                const std::filesystem::path& path, std::size_t columns,
                                const std::string& description);

/// The same, of text already read from `path` (a file opened without
/// following links).
std::vector<CsvRow> readCsvRows(const ConfigNode& n, const std::string& key,
                                const std::filesystem::path& path, std::istream& in,
                                std::size_t columns, const std::string& description);

/// The located error for line `line` of `path` (read at key `key`).
[[noreturn]] void failAt(const ConfigNode& n, const std::string& key,
                         const std::filesystem::path& path, int line, const std::string& message);

}  // namespace tofsim::config
