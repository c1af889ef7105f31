#include "SpadTableFile.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <utility>

#include "ConfigPath.h"
#include "CsvRows.h"
#include "ShortestNumber.h"
#include "TableText.h"
#include "tofsim/io/Npy.h"

namespace tofsim::config {

namespace {
io::NpyArray readNpyAt(const ConfigNode& n, const char* key, const std::filesystem::path& path,
                       const char* what) {
  try {
    return io::readNpy(path);
  } catch (const InputError& e) {
    n.failKey(key, std::string(e.what()) + " (" + what + ")");
  }
}

// One number per line; '#' comments, blank lines and a first non-numeric
// line (a header) are skipped.
std::vector<double> readColumnCsv(const ConfigNode& n, const char* key,
                                  const std::filesystem::path& path) {
  std::vector<double> values;
  for (const CsvRow& row : readCsvRows(n, key, path, 1, "a DNL value")) {
    values.push_back(row.cells[0]);
  }
  return values;
}

// Rows (delay, density) of a two-column CSV, each with its line for errors.
struct Rows {
  std::vector<double> delays, values;
  std::vector<std::string> where;  ///< "file:line" (CSV) or "file row k" (.npy)
};

Rows readTwoColumnCsv(const ConfigNode& n, const char* key, const std::filesystem::path& path) {
  Rows rows;
  for (const CsvRow& row : readCsvRows(n, key, path, 2, "delay in s, density")) {
    rows.delays.push_back(row.cells[0]);
    rows.values.push_back(row.cells[1]);
    rows.where.push_back(path.string() + ":" + std::to_string(row.line));
  }
  return rows;
}
}  // namespace

sensors::SpadAfterpulseTable parseAfterpulseDelayTable(const ConfigNode& n) {
  const char* key = "afterpulse_delay_table";
  const std::filesystem::path path = existingDataFile(n, key);
  const std::string file = path.string();
  const std::string ext = lowerExtension(path);
  Rows rows;
  if (ext == ".npy") {
    const io::NpyArray a =
        readNpyAt(n, key, path, "an afterpulse delay table .npy is a float32 (n, 2) array");
    if (a.shape.size() != 2 || a.shape[1] != 2) {
      std::string shape;
      for (std::size_t d : a.shape) shape += (shape.empty() ? "" : ", ") + std::to_string(d);
      n.failKey(key, file + ": expected shape (n, 2) (delay in s, density), got (" + shape + ")");
    }
    for (std::size_t k = 0; k < a.shape[0]; ++k) {
      rows.delays.push_back(a.data[2 * k]);
      rows.values.push_back(a.data[2 * k + 1]);
      rows.where.push_back(file + " row " + std::to_string(k));
    }
  } else if (ext == ".csv") {
    rows = readTwoColumnCsv(n, key, path);
  } else {
    n.failKey(key,
              "a .npy (n, 2) or two-column .csv file (got '" + path.filename().string() + "')");
  }
  if (rows.delays.size() < 2) {
    n.failKey(key, file + ": needs at least 2 rows (delay, density), got " +
                       std::to_string(rows.delays.size()));
  }
  double area = 0.0;
  for (std::size_t k = 0; k < rows.delays.size(); ++k) {
    const double t = rows.delays[k], v = rows.values[k];
    const std::string& at = rows.where[k];
    if (!std::isfinite(t) || t < 0.0) {
      n.failKey(key, at + ": delay " + shortest(t) + " s is " +
                         (std::isfinite(t) ? "negative" : "not finite") +
                         " (delays count from the end of the dead time)");
    }
    if (k > 0 && !(t > rows.delays[k - 1])) {
      n.failKey(key, at + ": delays must increase (" + shortest(t) + " s after " +
                         shortest(rows.delays[k - 1]) + " s)");
    }
    if (!std::isfinite(v) || v < 0.0) {
      n.failKey(key, at + ": density " + shortest(v) + " is " +
                         (std::isfinite(v) ? "negative" : "not finite") +
                         " (a delay density is >= 0)");
    }
    area += v;
  }
  if (!(area > 0.0)) n.failKey(key, file + ": the density has no area (every value is 0)");
  return sensors::afterpulseTable(file, rows.delays, rows.values);
}

sensors::SpadDnl parseDnl(const ConfigNode& n) {
  const char* key = "tdc_dnl";
  sensors::SpadDnl dnl;
  const ConfigNode node = n.child(key);
  if (node.isSequence()) {
    for (const ConfigNode& e : node.elements()) dnl.values.push_back(e.asDouble());
  } else {
    const std::filesystem::path path = existingDataFile(n, key);
    dnl.file = path.string();
    const std::string ext = lowerExtension(path);
    if (ext == ".npy") {
      const io::NpyArray a = readNpyAt(n, key, path, "a DNL .npy is a 1-D float32 array");
      if (a.shape.size() != 1) {
        n.failKey(key, dnl.file + ": expected a 1-D array (one DNL per bin), got rank " +
                           std::to_string(a.shape.size()));
      }
      dnl.values.assign(a.data.begin(), a.data.end());
    } else if (ext == ".csv") {
      dnl.values = readColumnCsv(n, key, path);
    } else {
      n.failKey(key, "a list of numbers, or a .npy or .csv file (got '" + path.filename().string() +
                         "')");
    }
  }
  const std::string where = dnl.file.empty() ? "" : dnl.file + ": ";
  if (dnl.values.empty()) n.failKey(key, where + "no values");
  for (std::size_t i = 0; i < dnl.values.size(); ++i) {
    const double d = dnl.values[i];
    if (!std::isfinite(d) || !(d > -1.0)) {
      n.failKey(
          key, where + "DNL " + shortest(d) + " of bin " + std::to_string(i) +
                   (std::isfinite(d) ? " gives a bin width LSB (1 + DNL) <= 0" : " is not finite"));
    }
  }
  return dnl;
}

void checkDnlSum(const ConfigNode& n, const sensors::SpadDnl& dnl) {
  double sum = 0.0;
  for (const double d : dnl.values) sum += d;
  const double tolerance = 1e-6 * static_cast<double>(dnl.values.size());
  if (std::fabs(sum) > tolerance) {
    n.failKey("tdc_dnl", (dnl.file.empty() ? "" : dnl.file + ": ") + "the DNL values sum to " +
                             shortest(sum) +
                             ", not 0 (the bins must fill the TDC's range; tolerance " +
                             shortest(tolerance) + ")");
  }
}

PixelMap readPixelMap(const ConfigNode& n, const char* key, const char* what, const char* valueName,
                      bool signedValues) {
  PixelMap map;
  const std::filesystem::path path = existingDataFile(n, key);
  map.file = path.string();
  const std::string expected = std::string("a ") + what + " is a 2-D float32 .npy";
  if (lowerExtension(path) != ".npy") {
    n.failKey(key, expected + " (got '" + path.filename().string() + "')");
  }
  const io::NpyArray a = readNpyAt(n, key, path, expected.c_str());
  if (a.shape.size() != 2) {
    n.failKey(key, map.file + ": expected a 2-D array (H, W), got rank " +
                       std::to_string(a.shape.size()));
  }
  map.height = static_cast<int32_t>(a.shape[0]);
  map.width = static_cast<int32_t>(a.shape[1]);
  for (std::size_t k = 0; k < a.data.size(); ++k) {
    const double v = a.data[k];
    if (!std::isfinite(v) || (v < 0.0 && !signedValues)) {
      n.failKey(key, map.file + ": " + valueName + " " + shortest(v) + " at (y, x) = (" +
                         std::to_string(k / map.width) + ", " + std::to_string(k % map.width) +
                         ") is " + (v < 0.0 ? "negative" : "not finite"));
    }
    map.values.push_back(v);
  }
  if (map.values.empty()) n.failKey(key, map.file + ": the array is empty");
  return map;
}

sensors::SpadDarkCountMap parseDarkCountMap(const ConfigNode& n) {
  PixelMap m = readPixelMap(n, "dark_count_map", "dark count map", "rate");
  sensors::SpadDarkCountMap map;
  map.file = m.file;
  map.width = m.width;
  map.height = m.height;
  map.rates_per_s = std::move(m.values);
  return map;
}

}  // namespace tofsim::config
