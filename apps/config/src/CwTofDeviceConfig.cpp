#include "CwTofDeviceConfig.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "ConfigPath.h"
#include "CwTofCaptureOrderConfig.h"
#include "CsvRows.h"
#include "ShortestNumber.h"
#include "SpadTableFile.h"
#include "TableText.h"
#include "tofsim/io/Npy.h"

namespace tofsim::config {

namespace {
using sensors::CwTofParams;

sensors::CwTofPixelMap readMap(const ConfigNode& n, const char* key, const char* what,
                               bool signedValues) {
  PixelMap m = readPixelMap(n, key, what, "value", signedValues);
  return {m.file, m.height, m.width, std::move(m.values)};
}

/// [a, b] as two numbers (integers when `integers`), or the element's error.
std::vector<double> pairOf(const ConfigNode& e, const char* what, bool integers) {
  if (!e.isSequence() || e.yaml().size() != 2) e.fail(std::string("expected ") + what);
  std::vector<double> xy;
  for (const ConfigNode& v : e.elements()) {
    const double d = v.asDouble();
    if (!std::isfinite(d)) v.fail("not a finite number");
    if (integers && d != std::floor(d)) v.fail("expected an integer");
    xy.push_back(d);
  }
  return xy;
}

sensors::CwTofCompanding parseCompanding(const ConfigNode& n) {
  const char* key = "companding";
  sensors::CwTofCompanding c;
  const ConfigNode node = n.child(key);
  // Where point i came from, for its error.
  std::vector<std::string> where;
  if (node.isSequence()) {
    int i = 0;
    for (const ConfigNode& e : node.elements()) {
      const std::vector<double> xy = pairOf(e, "[input DN, output DN]", false);
      c.input_dn.push_back(xy[0]);
      c.output_dn.push_back(xy[1]);
      where.push_back("point " + std::to_string(i++));
    }
  } else {
    const std::filesystem::path path = existingDataFile(n, key);
    if (lowerExtension(path) != ".csv") {
      n.failKey(key, "a list of [input, output] or a two-column .csv file (got '" +
                         path.filename().string() + "')");
    }
    c.file = path.string();
    for (const CsvRow& row : readCsvRows(n, key, path, 2, "input DN, output DN")) {
      c.input_dn.push_back(row.cells[0]);
      c.output_dn.push_back(row.cells[1]);
      where.push_back(c.file + ":" + std::to_string(row.line));
    }
  }
  if (c.input_dn.size() < 2) {
    n.failKey(key, (c.file.empty() ? "" : c.file + ": ") + "needs at least 2 points, got " +
                       std::to_string(c.input_dn.size()));
  }
  for (std::size_t i = 1; i < c.input_dn.size(); ++i) {
    if (!(c.input_dn[i] > c.input_dn[i - 1])) {
      n.failKey(key, where[i] + ": inputs must increase (" + shortest(c.input_dn[i]) + " after " +
                         shortest(c.input_dn[i - 1]) + ")");
    }
    if (c.output_dn[i] < c.output_dn[i - 1]) {
      n.failKey(key, where[i] + ": outputs must not decrease (" + shortest(c.output_dn[i]) +
                         " after " + shortest(c.output_dn[i - 1]) + ")");
    }
  }
  return c;
}

std::vector<sensors::CwTofCaptureStep> parseCaptureOrder(const ConfigNode& n,
                                                         const CwTofParams& p) {
  const ConfigNode node = n.child("capture_order");
  if (!node.isSequence()) n.failKey("capture_order", "expected a list of [f, n]");
  if (node.yaml().size() == 0) {
    n.failKey("capture_order",
              "lists no raws: write every [frequency index, phase step] once, in the order the "
              "raws are taken (e.g. " + suggestedCaptureOrder(p) +
                  "), or leave it out (or null) to have it derived");
  }
  const auto F = static_cast<int32_t>(p.frequencies_Hz.size());
  const int32_t N = p.phase_steps;
  std::vector<bool> seen(static_cast<std::size_t>(F) * N, false);
  std::vector<sensors::CwTofCaptureStep> order;
  for (const ConfigNode& e : node.elements()) {
    const std::vector<double> fn = pairOf(e, "[frequency index, phase step]", true);
    if (fn[0] < 0 || fn[0] >= F || fn[1] < 0 || fn[1] >= N) {
      e.fail("[" + shortest(fn[0]) + ", " + shortest(fn[1]) +
             "] is not a (frequency index, "
             "phase step) of " +
             std::to_string(F) + " frequencies x " + std::to_string(N) + " steps");
    }
    const sensors::CwTofCaptureStep step{static_cast<int32_t>(fn[0]), static_cast<int32_t>(fn[1])};
    const std::size_t j = static_cast<std::size_t>(step.frequency) * N + step.step;
    if (seen[j]) e.fail("[" + shortest(fn[0]) + ", " + shortest(fn[1]) + "] is listed twice");
    seen[j] = true;
    order.push_back(step);
  }
  if (order.size() != seen.size()) {
    n.failKey("capture_order", "lists " + std::to_string(order.size()) + " raws of " +
                                   std::to_string(seen.size()) +
                                   " (every [frequency index, phase step] once)");
  }
  return order;
}

sensors::CwTofNoiseTable parseNoiseTable(const ConfigNode& n) {
  const char* key = "noise_table";
  const std::filesystem::path path = existingDataFile(n, key);
  std::vector<double> means, samples;
  std::vector<std::string> where;
  const std::string ext = lowerExtension(path);
  if (ext == ".csv") {
    for (const CsvRow& row : readCsvRows(n, key, path, 2, "noise-free raw (integer), sample")) {
      means.push_back(row.cells[0]);
      samples.push_back(row.cells[1]);
      where.push_back(path.string() + ":" + std::to_string(row.line));
    }
  } else if (ext == ".npy") {
    io::NpyArray a;
    try {
      a = io::readNpy(path);
    } catch (const InputError& e) {
      n.failKey(key, std::string(e.what()) + " (a noise table .npy is a float32 (n, 2) array)");
    }
    if (a.shape.size() != 2 || a.shape[1] != 2) {
      n.failKey(key, path.string() + ": expected shape (n, 2) (noise-free raw, sample)");
    }
    for (std::size_t k = 0; k < a.shape[0]; ++k) {
      means.push_back(a.data[2 * k]);
      samples.push_back(a.data[2 * k + 1]);
      where.push_back(path.string() + " row " + std::to_string(k));
    }
  } else {
    n.failKey(key,
              "a two-column .csv or a .npy (n, 2) file (got '" + path.filename().string() + "')");
  }
  if (means.empty()) n.failKey(key, path.string() + ": no rows");
  double lo = means[0], hi = means[0];
  for (std::size_t k = 0; k < means.size(); ++k) {
    if (!std::isfinite(means[k]) || means[k] != std::floor(means[k]) || std::fabs(means[k]) > 1e9) {
      n.failKey(key, where[k] + ": the noise-free raw " + shortest(means[k]) +
                         " is not an integer (one sample set per integer value)");
    }
    if (!std::isfinite(samples[k])) n.failKey(key, where[k] + ": the sample is not finite");
    lo = std::min(lo, means[k]);
    hi = std::max(hi, means[k]);
  }
  if (hi - lo > 1e7) n.failKey(key, path.string() + ": the means span more than 1e7 values");
  sensors::CwTofNoiseTable table;
  table.file = path.string();
  table.first_mean_e = static_cast<int64_t>(lo);
  table.samples.resize(static_cast<std::size_t>(hi - lo) + 1);
  for (std::size_t k = 0; k < means.size(); ++k) {
    table.samples[static_cast<std::size_t>(means[k] - lo)].push_back(samples[k]);
  }
  return table;
}

void checkCwTofNoiseModel(const ConfigNode& n, const CwTofParams& p) {
  const bool table = p.noise_model == sensors::CwTofNoiseModel::Table;
  if (table && !p.noise_table.present()) {
    n.failKey("noise_model", "`table` needs `noise_table` (the measured samples)");
  }
  if (!table && p.noise_table.present()) {
    n.failKey("noise_table", "is for `noise_model: table`: set it, or remove this");
  }
  if (table && p.read_noise_e > 0.0) {
    n.failKey("read_noise", "the noise table holds the read noise: remove it");
  }
}

YAML::Node pairNode(double a, double b) {
  YAML::Node xy;
  xy.push_back(shortest(a));
  xy.push_back(shortest(b));
  xy.SetStyle(YAML::EmitterStyle::Flow);
  return xy;
}
}  // namespace

bool parseCwTofDeviceKey(const ConfigNode& n, std::string_view key, CwTofParams& p) {
  const std::string k(key);
  if (key == "delay_map" || key == "gain_map" || key == "offset_map") {
    if (!n.has(k)) return true;
    if (key == "delay_map") p.delay_map = readMap(n, "delay_map", "delay map", true);
    if (key == "gain_map") p.gain_map = readMap(n, "gain_map", "gain map", false);
    if (key == "offset_map") p.offset_map = readMap(n, "offset_map", "offset map", true);
    return true;
  }
  if (key == "companding") {
    if (n.has(k)) p.companding = parseCompanding(n);
    return true;
  }
  if (key == "capture_order") {
    // `capture_order: null` (read, so not an unknown key): derived after.
    if (n.optionalChild(k)) p.capture_order = parseCaptureOrder(n, p);
    return true;
  }
  if (key == "noise_table") {
    if (n.has(k)) p.noise_table = parseNoiseTable(n);
    return true;
  }
  return false;
}

void checkCwTofDevice(const ConfigNode& n, const CwTofParams& p) {
  const std::pair<const char*, bool> twoTapKeys[] = {
      {"ambient_suppression", p.ambient_suppression > 0.0},
      {"output_taps", p.output_taps},
      {"tap_b_gain", p.tap_b_gain != 1.0}};
  for (const auto& [key, set] : twoTapKeys) {
    if (set && p.taps != 2) n.failKey(key, "is for `taps: 2` (this sensor has one tap)");
  }
  const std::pair<const char*, bool> adcKeys[] = {{"adc_gain", p.adc_gain_dn_per_e != 1.0},
                                                  {"adc_offset", p.adc_offset_dn != 0.0},
                                                  {"companding", p.companding.present()}};
  for (const auto& [key, set] : adcKeys) {
    if (set && p.adc_bits == 0) n.failKey(key, "needs `adc_bits` (the ADC is off at 0)");
  }
  checkCwTofNoiseModel(n, p);
  const std::pair<const char*, bool> measured[] = {
      {"delay_sigma", p.delay_map.present() && p.delay_sigma_s > 0.0},
      {"gain_sigma", p.gain_map.present() && p.gain_sigma > 0.0},
      {"offset_sigma", p.offset_map.present() && p.offset_sigma_e > 0.0}};
  for (const auto& [key, both] : measured) {
    if (both) {
      n.failKey(key, "the measured map replaces the draw: remove `" + std::string(key) +
                         "` (or the map)");
    }
  }
}

void checkCwTofMapsFitImage(const ConfigNode& n, const CwTofParams& p,
                            const capture::Camera& camera) {
  const std::pair<const char*, const sensors::CwTofPixelMap*> maps[] = {
      {"delay_map", &p.delay_map}, {"gain_map", &p.gain_map}, {"offset_map", &p.offset_map}};
  for (const auto& [key, map] : maps) {
    if (map->present() && (map->height != camera.height || map->width != camera.width)) {
      n.failKey(key, map->file + " is " + std::to_string(map->height) + " x " +
                         std::to_string(map->width) + " (H x W) but the image is " +
                         std::to_string(camera.height) + " x " + std::to_string(camera.width));
    }
  }
}

bool emitCwTofDeviceKey(YAML::Node& n, std::string_view key, const CwTofParams& p) {
  const std::string k(key);
  const auto file = [&](const sensors::CwTofPixelMap& m) {
    if (m.present()) n[k] = m.file;
    return true;
  };
  if (key == "delay_map") return file(p.delay_map);
  if (key == "gain_map") return file(p.gain_map);
  if (key == "offset_map") return file(p.offset_map);
  if (key == "companding") {
    if (!p.companding.present()) return true;
    if (!p.companding.file.empty()) {
      n[k] = p.companding.file;
      return true;
    }
    for (std::size_t i = 0; i < p.companding.input_dn.size(); ++i) {
      n[k].push_back(pairNode(p.companding.input_dn[i], p.companding.output_dn[i]));
    }
    return true;
  }
  if (key == "noise_table") {
    if (p.noise_table.present()) n[k] = p.noise_table.file;
    return true;
  }
  if (key == "capture_order") {
    for (const sensors::CwTofCaptureStep& s : p.capture_order) {
      YAML::Node fn;
      fn.push_back(s.frequency);
      fn.push_back(s.step);
      fn.SetStyle(YAML::EmitterStyle::Flow);
      n[k].push_back(fn);
    }
    return true;
  }
  return false;
}

}  // namespace tofsim::config
