// Writes the effective sensor configuration back as YAML, in the keys and
// units parseSensors reads.
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>
#include <type_traits>

#include "SensorConfigType.h"
#include "ShortestNumber.h"
#include "tofsim/config/SensorConfig.h"

namespace tofsim::config {

namespace {
using namespace tofsim::sensors;

/// "100 ps": the largest unit giving a magnitude >= 1 that reads back exactly.
std::string duration(double s) {
  if (s == 0.0) return "0 s";
  const std::pair<double, const char*> units[] = {{1.0, "s"},   {1e-3, "ms"},  {1e-6, "us"},
                                                  {1e-9, "ns"}, {1e-12, "ps"}, {1e-15, "fs"}};
  for (const auto& [scale, name] : units) {
    if (std::abs(s) >= scale) return withUnit(s, scale, name, "s");
  }
  return withUnit(s, 1e-15, "fs", "s");
}

std::string frequency(double hz) {
  if (hz >= 1e9) return withUnit(hz, 1e9, "GHz", "Hz");
  if (hz >= 1e6) return withUnit(hz, 1e6, "MHz", "Hz");
  if (hz >= 1e3) return withUnit(hz, 1e3, "kHz", "Hz");
  return shortest(hz) + " Hz";
}

void emitCommon(YAML::Node& n, const SensorCommon& c) {
  if (c.channel.weights.empty()) {
    n["channel"] = c.channel.index;
  } else {
    for (double w : c.channel.weights) n["channel_weights"].push_back(shortest(w));
  }
  n["source_scale"] = shortest(c.radiometry.source_scale);
  n["etendue"] = shortest(c.radiometry.etendue_m2sr);
  n["optics_transmission"] = shortest(c.radiometry.optics_transmission);
  n["quantum_efficiency"] = shortest(c.radiometry.quantum_efficiency);
  n["wavelength"] = shortest(c.radiometry.wavelength_m) + " m";
}

void emitBins(YAML::Node& n, const InstrumentBins& b) {
  // 0 / unset mean "from the render" and are not explicit values: leave them out.
  if (b.bin_width_s > 0.0) n["bin_width"] = duration(b.bin_width_s);
  if (b.offset_s) n["bin_offset"] = duration(*b.offset_s);
  if (b.count > 0) n["bins"] = b.count;
}

}  // namespace

void SensorConfigType<StreakParams>::emit(YAML::Node& n, const StreakParams& p) {
  emitCommon(n, p.common);
  emitBins(n, p.bins);
  if (!p.rows.empty()) {
    for (int32_t r : p.rows) n["rows"].push_back(r);
  }
  n["time_fwhm"] = duration(p.time_fwhm_s);
  n["spatial_fwhm"] = shortest(p.spatial_fwhm_px);
  n["shot_noise"] = p.shot_noise;
  n["read_noise"] = shortest(p.read_noise_e);
  n["gain"] = shortest(p.gain_adu_per_e);
  n["saturation"] = shortest(p.saturation_adu);
  n["colormap"] = p.colormap;
}

void SensorConfigType<SpadParams>::emit(YAML::Node& n, const SpadParams& p) {
  emitCommon(n, p.common);
  emitBins(n, p.bins);
  n["mode"] = p.mode == SpadMode::Synchronous ? "synchronous" : "free_running";
  n["cycles"] = p.cycles;
  n["pulse_fwhm"] = duration(p.pulse_fwhm_s);
  n["jitter_fwhm"] = duration(p.jitter_fwhm_s);
  n["jitter_tail_fraction"] = shortest(p.jitter_tail_fraction);
  n["jitter_tail"] = duration(p.jitter_tail_s);
  n["pde"] = shortest(p.pde);
  n["ambient_rate"] = shortest(p.ambient_rate_per_s);
  n["dark_count_rate"] = shortest(p.dark_count_rate_per_s);
  n["dead_time"] = duration(p.dead_time_s);
  for (const auto& [x, y] : p.plot_pixels) {
    YAML::Node xy;
    xy.push_back(x);
    xy.push_back(y);
    xy.SetStyle(YAML::EmitterStyle::Flow);
    n["plot_pixels"].push_back(xy);
  }
  n["colormap"] = p.colormap;
}

void SensorConfigType<CwTofParams>::emit(YAML::Node& n, const CwTofParams& p) {
  emitCommon(n, p.common);
  for (double f : p.frequencies_Hz) n["frequencies"].push_back(frequency(f));
  n["phase_steps"] = p.phase_steps;
  n["waveform"] = p.waveform == Waveform::Sine ? "sine" : "square";
  n["ambient"] = shortest(p.ambient_e);
  n["shot_noise"] = p.shot_noise;
  n["read_noise"] = shortest(p.read_noise_e);
  n["max_depth"] = shortest(p.max_depth_m) + " m";
  n["colormap"] = p.colormap;
  n["multipath_by_order"] = p.multipath_by_order;
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

}  // namespace tofsim::config
