// Writes the effective sensor configuration back as YAML, in the keys and
// units parseSensors reads.
#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>
#include <type_traits>

#include "CwTofDeviceConfig.h"
#include "CwTofWaveformFile.h"
#include "FieldEmit.h"
#include "IrfFile.h"
#include "QuantityText.h"
#include "SensorConfigType.h"
#include "ShortestNumber.h"
#include "tofsim/config/SensorConfig.h"
#include "tofsim/sensors/SensorFields.h"

namespace tofsim::config {

namespace {
using namespace tofsim::sensors;

void emitCommon(YAML::Node& n, const SensorCommon& c) {
  // `channel` or `channel_weights`: one choice of two keys, by hand.
  // The default (the sum of the channels) is written as no key at all.
  if (!c.channel.weights.empty()) {
    for (double w : c.channel.weights) n["channel_weights"].push_back(shortest(w));
  } else if (c.channel.index != ChannelSelection::kSumOfChannels) {
    n["channel"] = c.channel.index;
  }
  emitFields(n, kRadiometryFields, c.radiometry);
}

}  // namespace

void SensorConfigType<StreakParams>::emit(YAML::Node& n, const StreakParams& p) {
  emitCommon(n, p.common);
  emitFields(n, kBinsFields, p.bins);
  emitFields(n, kStreakFields, p, [&](std::string_view key) {
    if (key == "rows") {
      for (int32_t r : p.rows) n["rows"].push_back(r);
    }
  });
}

void SensorConfigType<SpadParams>::emit(YAML::Node& n, const SpadParams& p) {
  emitCommon(n, p.common);
  emitFields(n, kBinsFields, p.bins);
  emitFields(n, kSpadFields, p, [&](std::string_view key) {
    if (key == "preset") {
      if (!p.preset.empty()) n["preset"] = p.preset;
      return;
    }
    if (key == "irf") {
      if (p.irf.present()) n["irf"] = irfToYaml(p.irf);
      return;
    }
    if (key == "tdc_dnl") {
      if (!p.tdc_dnl.present()) return;
      if (!p.tdc_dnl.file.empty()) {
        n["tdc_dnl"] = p.tdc_dnl.file;
        return;
      }
      for (double d : p.tdc_dnl.values) n["tdc_dnl"].push_back(shortest(d));
      n["tdc_dnl"].SetStyle(YAML::EmitterStyle::Flow);
      return;
    }
    if (key == "dark_count_map") {
      if (p.dark_count_map.present()) n["dark_count_map"] = p.dark_count_map.file;
      return;
    }
    if (key == "afterpulse_delay_table") {
      if (p.afterpulse_delay_table.present()) n[key.data()] = p.afterpulse_delay_table.file;
      return;
    }
    if (key == "afterpulse_delay") {
      if (p.afterpulse_delay_table.present()) return;  // exclusive: the table gives the delays
      if (p.afterpulse_delays_s.size() == 1) {
        n[key.data()] = durationText(p.afterpulse_delays_s[0]);
      } else {
        for (double d : p.afterpulse_delays_s) n[key.data()].push_back(durationText(d));
      }
      return;
    }
    if (key == "afterpulse_weights") {
      for (double w : p.afterpulse_weights) n[key.data()].push_back(w);
      return;
    }
    if (key != "plot_pixels") return;
    for (const auto& [x, y] : p.plot_pixels) {
      YAML::Node xy;
      xy.push_back(x);
      xy.push_back(y);
      xy.SetStyle(YAML::EmitterStyle::Flow);
      n["plot_pixels"].push_back(xy);
    }
  });
}

void SensorConfigType<CwTofParams>::emit(YAML::Node& n, const CwTofParams& p) {
  emitCommon(n, p.common);
  emitFields(n, kCwTofFields, p, [&](std::string_view key) {
    if (key == "preset") {
      if (!p.preset.empty()) n["preset"] = p.preset;
      return;
    }
    if (emitCwTofDeviceKey(n, key, p)) return;
    if (key == "correlation") {
      if (!p.correlation.empty()) n["correlation"] = correlationToYaml(p.correlation);
      return;
    }
    if (key != "frequencies") return;
    for (double f : p.frequencies_Hz) n["frequencies"].push_back(frequencyText(f));
  });
}

YAML::Node sensorsToYaml(const std::vector<SensorSpec>& specs) {
  YAML::Node list(YAML::NodeType::Sequence);
  for (const SensorSpec& spec : specs) {
    YAML::Node n;
    n["type"] = sensorTypeName(spec.params);
    n["name"] = spec.name;
    std::visit([&n](const auto& p) { SensorConfigType<std::decay_t<decltype(p)>>::emit(n, p); },
               spec.params);
    list.push_back(n);
  }
  return list;
}

void SensorConfigType<ApdParams>::emit(YAML::Node& n, const ApdParams& p) {
  emitCommon(n, p.common);
  emitFields(n, kBinsFields, p.bins);
  emitFields(n, kApdFields, p);
}

}  // namespace tofsim::config
