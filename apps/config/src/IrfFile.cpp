#include "IrfFile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ConfigPath.h"
#include "CsvRows.h"
#include "QuantityText.h"
#include "ShortestNumber.h"
#include "TableText.h"
#include "tofsim/config/Units.h"
#include "tofsim/io/Npy.h"

namespace tofsim::config {

namespace {
using sensors::SpadIrf;

struct Samples {
  std::vector<double> values;
  double first_time_s = 0.0;
  double width_s = 0.0;  ///< 0 for .npy: from `bin_width`
};

// Two columns, time (s) and value, comma separated; '#' lines are comments
// and a first line that is not two numbers a header.
Samples readCsv(const ConfigNode& n, const std::filesystem::path& path) {
  Samples s;
  std::vector<double> times;
  int lineNo = 0;
  const auto failLine = [&](const std::string& message) {
    failAt(n, "file", path, lineNo, message);
  };
  for (const CsvRow& row : readCsvRows(n, "file", path, 2, "time in s, value")) {
    lineNo = row.line;
    const double time = row.cells[0], value = row.cells[1];
    if (value < 0.0) failLine("negative value " + shortest(value) + " (an IRF is a density)");
    if (times.size() >= 2) {
      const double step = times[1] - times[0];
      const double expected = times[0] + static_cast<double>(times.size()) * step;
      if (std::fabs(time - expected) > 1e-6 * step) {
        failLine("times are not evenly spaced (" + shortest(time) + " s, expected " +
                 shortest(expected) + " s)");
      }
    } else if (times.size() == 1 && !(time > times[0])) {
      failLine("times must increase (" + shortest(time) + " s after " + shortest(times[0]) + " s)");
    }
    times.push_back(time);
    s.values.push_back(value);
  }
  if (times.size() < 2) {
    n.failKey("file",
              path.string() + ": needs at least 2 rows (time, value) to give the bin width");
  }
  s.first_time_s = times[0];
  s.width_s = times[1] - times[0];
  return s;
}

Samples readNpySamples(const ConfigNode& n, const std::filesystem::path& path) {
  io::NpyArray a;
  try {
    a = io::readNpy(path);
  } catch (const InputError& e) {
    n.failKey("file", std::string(e.what()) + " (an IRF .npy is a 1-D float32 array)");
  }
  if (a.shape.size() != 1) {
    n.failKey("file", path.string() + ": expected a 1-D array (K samples), got rank " +
                          std::to_string(a.shape.size()));
  }
  Samples s;
  for (std::size_t k = 0; k < a.data.size(); ++k) {
    const double v = a.data[k];
    if (!std::isfinite(v) || v < 0.0) {
      n.failKey("file", path.string() + ": value " + shortest(v) + " at index " +
                            std::to_string(k) + " is " + (v < 0.0 ? "negative" : "not finite") +
                            " (an IRF is a density)");
    }
    s.values.push_back(v);
  }
  if (s.values.empty()) n.failKey("file", path.string() + ": the array is empty");
  return s;
}
}  // namespace

SpadIrf parseIrf(const ConfigNode& n) {
  if (!n.isMap()) n.fail("expected a mapping (file, bin_width, t0, floor)");
  SpadIrf irf;
  const std::filesystem::path path = existingDataFile(n, "file", "IRF file");
  irf.file = path.string();
  const std::string ext = lowerExtension(path);
  if (ext != ".npy" && ext != ".csv") {
    n.failKey("file", "an IRF file is .npy or .csv (got '" + path.filename().string() + "')");
  }

  irf.bin_width_s = n.getDuration_s("bin_width", 0.0);
  Samples s;
  if (ext == ".npy") {
    if (!n.has("bin_width")) n.failKey("file", "a .npy IRF needs `bin_width` (its sample spacing)");
    if (!(irf.bin_width_s > 0.0)) {
      n.failKey("bin_width", "must be > 0 (got " + shortest(irf.bin_width_s) + ")");
    }
    s = readNpySamples(n, path);
    s.width_s = irf.bin_width_s;
  } else {
    if (n.has("bin_width")) {
      n.failKey("bin_width", "a CSV IRF takes its bin width from the time column: remove it");
    }
    s = readCsv(n, path);
  }

  if (const auto t0 = n.optionalChild("t0")) {
    const std::string mode = t0->asString();
    if (mode == "peak") {
      irf.t0 = SpadIrf::TimeZero::Peak;
    } else if (mode == "centroid") {
      irf.t0 = SpadIrf::TimeZero::Centroid;
    } else {
      irf.t0 = SpadIrf::TimeZero::Time;
      try {
        irf.t0_s = parseDuration_s(mode);
      } catch (const std::invalid_argument& e) {
        t0->fail("must be peak, centroid or a time (" + std::string(e.what()) + ")");
      }
    }
  }
  // A time zero outside the response would delay (or advance) all of the
  // light by more than the response itself: a wrong unit or a time of
  // another axis, not a response. The support check of the kernel
  // (checkSensorKernels) then bounds the span by the TDC's bins.
  if (irf.t0 == SpadIrf::TimeZero::Time) {
    const double lo = s.first_time_s - 0.5 * s.width_s;
    const double hi = lo + static_cast<double>(s.values.size()) * s.width_s;
    if (!(irf.t0_s >= lo && irf.t0_s <= hi)) {
      n.failKey("t0", "t0 " + durationText(irf.t0_s) + " lies outside the response in " +
                          path.string() + ", which spans [" + readableDuration(lo) + ", " +
                          readableDuration(hi) +
                          "] on its own time axis (t0 is a time of that response: peak, "
                          "centroid or a time within it)");
    }
  }
  irf.floor = n.getDouble("floor", 0.0);
  if (!(irf.floor >= 0.0)) n.failKey("floor", "must be >= 0 (got " + shortest(irf.floor) + ")");

  double area = 0.0;
  for (double& v : s.values) {
    v = std::max(0.0, v - irf.floor);
    area += v;
  }
  if (!(area > 0.0)) {
    n.failKey("file", irf.file + ": no area above the floor " + shortest(irf.floor) +
                          " (every value is <= it)");
  }
  irf.values = std::move(s.values);
  irf.first_time_s = s.first_time_s;
  irf.sample_width_s = s.width_s;
  return irf;
}

YAML::Node irfToYaml(const SpadIrf& irf) {
  YAML::Node n;
  n["file"] = irf.file;
  if (irf.bin_width_s > 0.0) n["bin_width"] = durationText(irf.bin_width_s);
  switch (irf.t0) {
    case SpadIrf::TimeZero::Peak:
      n["t0"] = "peak";
      break;
    case SpadIrf::TimeZero::Centroid:
      n["t0"] = "centroid";
      break;
    case SpadIrf::TimeZero::Time:
      n["t0"] = durationText(irf.t0_s);
      break;
  }
  n["floor"] = irf.floor;
  return n;
}

}  // namespace tofsim::config
