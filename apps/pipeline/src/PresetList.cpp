#include "tofsim/pipeline/PresetList.h"

#include <string_view>
#include <type_traits>

#include "SensorParametersJson.h"
#include "tofsim/config/LidarPresets.h"
#include "tofsim/sensors/CwTofPresets.h"
#include "tofsim/sensors/SensorFields.h"
#include "tofsim/sensors/SpadPresets.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {

using json = nlohmann::ordered_json;

// The parameter JSON's value for config key `key` as "value unit": its
// Field's JSON name carries the SI unit after the key (bin_width_s,
// dark_count_rate_per_s); the custom keys by hand (frequencies_Hz,
// capture.order; companding absent: linear; bin_width_s).
template <class Table>
std::string valueOf(const json& all, const Table& table, std::string_view key) {
  std::string name;
  sensors::forEachField(table, [&](const auto& entry) {
    if constexpr (sensors::kIsField<std::decay_t<decltype(entry)>>) {
      if (key == entry.name && entry.info.json) name = entry.info.json;
    }
  });
  if (key == "frequencies") name = "frequencies_Hz";
  if (key == "capture_order" && all.contains("capture")) return all["capture"]["order"].dump();
  if (key == "companding" && !all.contains("companding")) return "none (linear)";
  // The instrument bins' keys (bin_width) are written resolved, in s.
  if (name.empty() && all.contains(std::string(key) + "_s")) name = std::string(key) + "_s";
  if (name.empty()) name = key;
  if (!all.contains(name)) return "(set)";
  const std::string unit = name.size() > key.size() + 1 ? name.substr(key.size() + 1) : "";
  return all[name].dump() + (unit.empty() ? "" : " " + unit);
}

template <class Params, class Table>
std::string describe(const sensors::DevicePreset<Params>& preset, const char* type,
                     const Table& table) {
  Params p{};
  preset.apply(p);
  // The preset's own bins against a nominal render axis: what the preset
  // leaves unset follows the render.
  TimeAxis render;
  render.bin_width_s = 1e-11;
  render.bins = 1;
  const json all = sensorParametersJson(sensors::SensorParams{p}, render);
  std::string out = std::string(preset.name) + " (" + type + "): " + preset.device + "\n";
  if (preset.width > 0) {
    out += "  pixel array: " + std::to_string(preset.width) + " x " +
           std::to_string(preset.height) + "\n";
  }
  for (const sensors::PresetValue& v : preset.values) {
    out += std::string("  ") + v.key + " = " + valueOf(all, table, v.key);
    out += v.source ? std::string("  source: ") + v.source
                    : std::string("  assumed: ") + (v.note ? v.note : "");
    out += "\n";
  }
  if (!preset.sources.empty()) out += "  sources:\n";
  for (const char* s : preset.sources) out += std::string("    ") + s + "\n";
  return out;
}

}  // namespace

std::string describePresets(const std::string& name) {
  std::string out, names;
  for (const sensors::SpadPreset& p : sensors::spadPresets()) {
    names += std::string(names.empty() ? "" : ", ") + p.name;
    if (name.empty() || name == p.name) out += (out.empty() ? "" : "\n") + describe(p, "spad", sensors::kSpadFields);
  }
  for (const sensors::CwTofPreset& p : sensors::cwtofPresets()) {
    names += std::string(", ") + p.name;
    if (name.empty() || name == p.name) out += (out.empty() ? "" : "\n") + describe(p, "cwtof", sensors::kCwTofFields);
  }
  for (const config::LidarPreset& p : config::lidarPresets()) {
    names += std::string(", ") + p.name;
    if (name.empty() || name == p.name) out += (out.empty() ? "" : "\n") + config::describeLidarPreset(p);
  }
  if (out.empty()) throw InputError("no preset '" + name + "' (presets: " + names + ")");
  if (name.empty()) {
    out += "\nUse one as `preset: <name>` in a sensor (configs/README.md, Sensors) or as "
           "`lidar.preset: <name>` (configs/README.md, `lidar`); explicit keys replace its "
           "values.\n";
  }
  return out;
}

}  // namespace tofsim::pipeline
