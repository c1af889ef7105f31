#include "CwTofWaveformFile.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "ConfigPath.h"
#include "CsvRows.h"
#include "ShortestNumber.h"
#include "TableText.h"
#include "tofsim/io/Npy.h"

namespace tofsim::config {

namespace {
using sensors::CorrelationWaveform;
constexpr double kTwoPi = 2.0 * M_PI;

/// M samples at phases 2 pi j / M.
void evenlySpaced(CorrelationWaveform& w) {
  w.phases_rad.clear();
  const std::size_t M = w.values.size();
  for (std::size_t j = 0; j < M; ++j) w.phases_rad.push_back(kTwoPi * j / M);
}

// Rows `phase_rad,value` ('#' comments, a first non-numeric row a header):
// phases increasing over one period [0, 2 pi]; a row at 2 pi closes the
// period and must repeat the value at phase 0 (it is then dropped).
void readCsv(const ConfigNode& n, const std::filesystem::path& path, CorrelationWaveform& w) {
  int lineNo = 0;
  const auto failLine = [&](const std::string& message) {
    failAt(n, "file", path, lineNo, message);
  };
  for (const CsvRow& row : readCsvRows(n, "file", path, 2, "phase in rad, value")) {
    lineNo = row.line;
    const double phase = row.cells[0], value = row.cells[1];
    if (phase < 0.0 || phase > kTwoPi + 1e-9) {
      failLine("phase " + shortest(phase) + " rad is outside one period [0, 2 pi]");
    }
    if (!w.phases_rad.empty() && !(phase > w.phases_rad.back())) {
      failLine("phases must increase (" + shortest(phase) + " rad after " +
               shortest(w.phases_rad.back()) + " rad)");
    }
    if (phase >= kTwoPi - 1e-9) {  // the period's end: the same point as phase 0
      if (w.phases_rad.empty() || w.phases_rad[0] != 0.0) {
        failLine("a row at 2 pi closes the period, but there is no row at phase 0");
      }
      if (std::fabs(value - w.values[0]) > 1e-9 * std::max(1.0, std::fabs(w.values[0]))) {
        failLine("not periodic: the value at 2 pi (" + shortest(value) +
                 ") differs from the value at phase 0 (" + shortest(w.values[0]) + ")");
      }
      continue;
    }
    w.phases_rad.push_back(phase);
    w.values.push_back(value);
  }
}

void readNpy(const ConfigNode& n, const std::filesystem::path& path, CorrelationWaveform& w) {
  io::NpyArray a;
  try {
    a = io::readNpy(path);
  } catch (const InputError& e) {
    n.failKey("file", std::string(e.what()) + " (a waveform .npy is a 1-D float32 array)");
  }
  if (a.shape.size() != 1) {
    n.failKey("file", path.string() + ": expected a 1-D array (M samples per period), got rank " +
                          std::to_string(a.shape.size()));
  }
  for (std::size_t j = 0; j < a.data.size(); ++j) {
    if (!std::isfinite(a.data[j])) {
      n.failKey("file", path.string() + ": sample " + std::to_string(j) + " is not finite");
    }
    w.values.push_back(a.data[j]);
  }
  evenlySpaced(w);
}

/// One waveform mapping.
CorrelationWaveform parseOne(const ConfigNode& n) {
  if (!n.isMap()) n.fail("expected a mapping with `harmonics`, `samples` or `file`");
  const int forms = n.has("harmonics") + n.has("samples") + n.has("file");
  if (forms != 1) n.fail("give exactly one of `harmonics`, `samples` or `file`");
  CorrelationWaveform w;
  std::string where;
  if (auto h = n.optionalChild("harmonics")) {
    if (!h->isSequence()) h->fail("expected a list of [re, im] pairs: c_1 .. c_K");
    for (const ConfigNode& e : h->elements()) {
      if (!e.isSequence() || e.yaml().size() != 2) e.fail("expected [re, im]");
      const std::vector<ConfigNode> c = e.elements();
      w.harmonics.emplace_back(c[0].asDouble(), c[1].asDouble());
    }
    if (w.harmonics.empty()) h->fail("must list at least one harmonic");
  } else if (auto s = n.optionalChild("samples")) {
    if (!s->isSequence()) s->fail("expected a list of values (M samples per period)");
    for (const ConfigNode& e : s->elements()) w.values.push_back(e.asDouble());
    if (w.values.empty()) s->fail("must list at least two samples");
    evenlySpaced(w);
  } else {
    const std::filesystem::path path = existingDataFile(n, "file");
    w.file = path.string();
    where = w.file + ": ";
    const std::string ext = lowerExtension(path);
    if (ext == ".csv") {
      readCsv(n, path, w);
    } else if (ext == ".npy") {
      readNpy(n, path, w);
    } else {
      n.failKey("file", "a waveform file is .csv (phase_rad,value) or .npy (got '" +
                            path.filename().string() + "')");
    }
  }
  const std::string problem = sensors::waveformProblem(w);
  if (!problem.empty()) {
    const char* key = n.has("harmonics") ? "harmonics" : n.has("samples") ? "samples" : "file";
    n.failKey(key, where + problem);
  }
  return w;
}
}  // namespace

std::vector<CorrelationWaveform> parseCorrelation(const ConfigNode& n, std::size_t frequencies) {
  const ConfigNode node = n.child("correlation");
  if (!node.isSequence()) return {parseOne(node)};
  std::vector<CorrelationWaveform> waveforms;
  for (const ConfigNode& e : node.elements()) waveforms.push_back(parseOne(e));
  if (waveforms.size() != frequencies) {
    n.failKey("correlation", "lists " + std::to_string(waveforms.size()) + " waveforms for " +
                                 std::to_string(frequencies) +
                                 " frequencies: give one mapping for all, or one per frequency");
  }
  return waveforms;
}

YAML::Node correlationToYaml(const std::vector<CorrelationWaveform>& waveforms) {
  const auto one = [](const CorrelationWaveform& w) {
    YAML::Node n;
    if (!w.file.empty()) {
      n["file"] = w.file;
    } else if (w.fourier()) {
      for (const auto& c : w.harmonics) {
        YAML::Node pair;
        pair.push_back(shortest(c.real()));
        pair.push_back(shortest(c.imag()));
        pair.SetStyle(YAML::EmitterStyle::Flow);
        n["harmonics"].push_back(pair);
      }
    } else {
      for (double v : w.values) n["samples"].push_back(shortest(v));
      n["samples"].SetStyle(YAML::EmitterStyle::Flow);
    }
    return n;
  };
  if (waveforms.size() == 1) return one(waveforms[0]);
  YAML::Node list(YAML::NodeType::Sequence);
  for (const CorrelationWaveform& w : waveforms) list.push_back(one(w));
  return list;
}

}  // namespace tofsim::config
