#include "SpadTableFile.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <utility>

#include "ConfigPath.h"
#include "CsvRows.h"
#include "DelayTableFile.h"
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

}  // namespace

sensors::SpadAfterpulseTable parseAfterpulseDelayTable(const ConfigNode& n) {
  const DelayTableWords words{"an afterpulse delay table", "density",
                              "delays count from the end of the dead time",
                              "a delay density is >= 0"};
  DelayRows rows = readDelayTable(n, "afterpulse_delay_table", words);
  return sensors::afterpulseTable(rows.file, std::move(rows.delays), rows.values);
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
