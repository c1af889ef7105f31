#include "DelayTableFile.h"

#include <cmath>
#include <filesystem>

#include "ConfigPath.h"
#include "CsvRows.h"
#include "ShortestNumber.h"
#include "TableText.h"
#include "tofsim/io/FileBytes.h"

namespace tofsim::config {

namespace {
// A delay table is a few thousand rows: 64 MiB is far past any.
constexpr std::size_t kMaxTableBytes = std::size_t{64} << 20;

struct Located {
  DelayRows rows;
  std::vector<std::string> where;  ///< "file:line" (CSV) or "file row k" (.npy)
};

Located readRows(const ConfigNode& n, const char* key, const DelayTableWords& w) {
  const std::filesystem::path path = existingDataFile(n, key);
  Located r;
  r.rows.file = path.string();
  const std::string& file = r.rows.file;
  const std::string ext = lowerExtension(path);
  if (ext != ".npy" && ext != ".csv") {
    n.failKey(key, "a .npy (n, 2) or two-column .csv file (got '" + path.filename().string() + "')");
  }
  const std::string columns = "delay in " + w.delayUnit + ", " + w.value;
  std::string bytes;
  io::NpyArray a;
  try {
    bytes = io::readFileNoFollow(path, kMaxTableBytes);
    if (ext == ".npy") a = io::parseNpy(bytes, file);
  } catch (const InputError& e) {
    n.failKey(key, std::string(e.what()) + " (" + w.table +
                       (ext == ".npy" ? " .npy is a float32 or float64 (n, 2) array)" : " file)"));
  }
  if (ext == ".csv") {
    for (const CsvRow& row : readCsvText(n, key, path, bytes, 2, columns)) {
      r.rows.delays.push_back(row.cells[0]);
      r.rows.values.push_back(row.cells[1]);
      r.where.push_back(file + ":" + std::to_string(row.line));
    }
    return r;
  }
  if (a.shape.size() != 2 || a.shape[1] != 2) {
    std::string shape;
    for (std::size_t d : a.shape) shape += (shape.empty() ? "" : ", ") + std::to_string(d);
    n.failKey(key, file + ": expected shape (n, 2) (" + columns + "), got (" + shape + ")");
  }
  for (std::size_t k = 0; k < a.shape[0]; ++k) {
    r.rows.delays.push_back(a.data[2 * k]);
    r.rows.values.push_back(a.data[2 * k + 1]);
    r.where.push_back(file + " row " + std::to_string(k));
  }
  return r;
}
}  // namespace

DelayRows readDelayTable(const ConfigNode& n, const char* key, const DelayTableWords& w) {
  Located r = readRows(n, key, w);
  const DelayRows& rows = r.rows;
  const std::string& unit = w.delayUnit;
  if (rows.delays.size() < 2) {
    n.failKey(key, rows.file + ": needs at least 2 rows (delay, " + w.value + "), got " +
                       std::to_string(rows.delays.size()));
  }
  double area = 0.0;
  for (std::size_t k = 0; k < rows.delays.size(); ++k) {
    const double t = rows.delays[k], v = rows.values[k];
    const std::string& at = r.where[k];
    if (!std::isfinite(t) || t < 0.0) {
      n.failKey(key, at + ": delay " + shortest(t) + " " + unit + " is " +
                         (std::isfinite(t) ? "negative" : "not finite") + " (column 1; " +
                         w.delayNote + ")");
    }
    if (k > 0 && !(t > rows.delays[k - 1])) {
      n.failKey(key, at + ": delays must increase (column 1: " + shortest(t) + " " + unit +
                         " after " + shortest(rows.delays[k - 1]) + " " + unit + ")");
    }
    if (!std::isfinite(v) || v < 0.0) {
      n.failKey(key, at + ": " + w.value + " " + shortest(v) + " is " +
                         (std::isfinite(v) ? "negative" : "not finite") + " (column 2; " +
                         w.valueNote + ")");
    }
    if (k > 0) area += 0.5 * (t - rows.delays[k - 1]) * (v + rows.values[k - 1]);
  }
  if (!(area > 0.0)) {
    n.failKey(key, rows.file + ": the " + w.value + " has no area (every value is 0)");
  }
  if (!std::isfinite(area)) {
    n.failKey(key, rows.file + ": the " + w.value + "'s area overflows (values or delays too large)");
  }
  return std::move(r.rows);
}

}  // namespace tofsim::config
