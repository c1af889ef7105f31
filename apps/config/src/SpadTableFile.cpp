#include "SpadTableFile.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "ConfigPath.h"
#include "ShortestNumber.h"
#include "TableText.h"
#include "tofsim/io/Npy.h"

namespace tofsim::config {

namespace {
std::filesystem::path existingFile(const ConfigNode& n, const char* key) {
  const std::filesystem::path path = configRelativePath(n, n.requireString(key));
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    n.failKey(key, "file not found: " + path.string());
  }
  return path;
}

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
  std::ifstream in(path);
  if (!in) n.failKey(key, "cannot read " + path.string());
  std::vector<double> values;
  std::string line;
  int lineNo = 0;
  bool data = false;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string t = trimmedText(line);
    if (t.empty() || t[0] == '#') continue;
    double v = 0.0;
    const bool number = wholeNumber(t, v);
    if (!number && !data) {  // a header
      data = true;
      continue;
    }
    data = true;
    if (!number) {
      n.failKey(key, path.string() + ":" + std::to_string(lineNo) +
                         ": expected one number per line (a DNL value), got '" + t + "'");
    }
    values.push_back(v);
  }
  return values;
}
}  // namespace

sensors::SpadDnl parseDnl(const ConfigNode& n) {
  const char* key = "tdc_dnl";
  sensors::SpadDnl dnl;
  const ConfigNode node = n.child(key);
  if (node.isSequence()) {
    for (const ConfigNode& e : node.elements()) dnl.values.push_back(e.asDouble());
  } else {
    const std::filesystem::path path = existingFile(n, key);
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
  double sum = 0.0;
  for (std::size_t i = 0; i < dnl.values.size(); ++i) {
    const double d = dnl.values[i];
    if (!std::isfinite(d) || !(d > -1.0)) {
      n.failKey(
          key, where + "DNL " + shortest(d) + " of bin " + std::to_string(i) +
                   (std::isfinite(d) ? " gives a bin width LSB (1 + DNL) <= 0" : " is not finite"));
    }
    sum += d;
  }
  const double tolerance = 1e-6 * static_cast<double>(dnl.values.size());
  if (std::fabs(sum) > tolerance) {
    n.failKey(key, where + "the DNL values sum to " + shortest(sum) +
                       ", not 0 (the bins must fill the TDC's range; tolerance " +
                       shortest(tolerance) + ")");
  }
  return dnl;
}

sensors::SpadDarkCountMap parseDarkCountMap(const ConfigNode& n) {
  const char* key = "dark_count_map";
  sensors::SpadDarkCountMap map;
  const std::filesystem::path path = existingFile(n, key);
  map.file = path.string();
  if (lowerExtension(path) != ".npy") {
    n.failKey(key,
              "a dark count map is a 2-D float32 .npy (got '" + path.filename().string() + "')");
  }
  const io::NpyArray a = readNpyAt(n, key, path, "a dark count map is a 2-D float32 .npy");
  if (a.shape.size() != 2) {
    n.failKey(key, map.file + ": expected a 2-D array (H, W), got rank " +
                       std::to_string(a.shape.size()));
  }
  map.height = static_cast<int32_t>(a.shape[0]);
  map.width = static_cast<int32_t>(a.shape[1]);
  for (std::size_t k = 0; k < a.data.size(); ++k) {
    const double v = a.data[k];
    if (!std::isfinite(v) || v < 0.0) {
      n.failKey(key, map.file + ": rate " + shortest(v) + " at (y, x) = (" +
                         std::to_string(k / map.width) + ", " + std::to_string(k % map.width) +
                         ") is " + (v < 0.0 ? "negative" : "not finite"));
    }
    map.rates_per_s.push_back(v);
  }
  if (map.rates_per_s.empty()) n.failKey(key, map.file + ": the array is empty");
  return map;
}

}  // namespace tofsim::config
