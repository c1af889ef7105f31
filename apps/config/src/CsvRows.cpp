#include "CsvRows.h"

#include <fstream>
#include <sstream>

#include "TableText.h"

namespace tofsim::config {

void failAt(const ConfigNode& n, const std::string& key, const std::filesystem::path& path,
            int line, const std::string& message) {
  n.failKey(key, path.string() + ":" + std::to_string(line) + ": " + message);
}

std::vector<CsvRow> readCsvRows(const ConfigNode& n, const std::string& key,
                                const std::filesystem::path& path, std::size_t columns,
                                const std::string& description) {
  std::ifstream in(path);
  if (!in) n.failKey(key, "cannot read " + path.string());
  return readCsvRows(n, key, path, in, columns, description);
}

std::vector<CsvRow> readCsvRows(const ConfigNode& n, const std::string& key,
                                const std::filesystem::path& path, std::istream& in,
                                std::size_t columns, const std::string& description) {
  std::vector<CsvRow> rows;
  std::string line;
  int lineNo = 0;
  bool data = false;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string t = trimmedText(line);
    if (t.empty() || t[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream parts(t);
    for (std::string cell; std::getline(parts, cell, ',');) cells.push_back(cell);
    if (t.back() == ',') cells.push_back("");
    CsvRow row{lineNo, std::vector<double>(cells.size(), 0.0)};
    bool numbers = cells.size() == columns;
    for (std::size_t c = 0; c < cells.size() && numbers; ++c) {
      numbers = wholeNumber(cells[c], row.cells[c]);
    }
    if (!numbers && !data && cells.size() == columns) {  // a header: "time_s,value"
      data = true;
      continue;
    }
    data = true;
    if (cells.size() != columns) {
      failAt(n, key, path, lineNo,
             "expected " + std::to_string(columns) + " column" + (columns == 1 ? "" : "s") + " (" +
                 description + "), got " + std::to_string(cells.size()));
    }
    if (!numbers) {
      failAt(n, key, path, lineNo,
             (columns == 1 ? std::string("expected one finite number")
                           : "expected " + std::to_string(columns) + " finite numbers") +
                 " (" + description + "), got '" + t + "'");
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace tofsim::config
