#include "SensorParametersJson.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "FieldJson.h"
#include "tofsim/sensors/Common.h"
#include "tofsim/sensors/CwTofPresets.h"
#include "tofsim/sensors/SensorFields.h"
#include "tofsim/sensors/SpadPresets.h"

namespace tofsim::pipeline {

namespace {
using json = nlohmann::ordered_json;
using namespace tofsim::sensors;

json commonJson(const SensorCommon& c) {
  json j;
  // `channel` or `channel_weights`: one choice of two keys, by hand.
  // The default, the sum of the channels, is written "channel": "sum".
  if (c.channel.weights.empty() && c.channel.index == ChannelSelection::kSumOfChannels) {
    j["channel"] = "sum";
  } else if (c.channel.weights.empty()) {
    j["channel"] = c.channel.index;
  } else {
    j["channel_weights"] = c.channel.weights;
  }
  fieldsJson(j, kRadiometryFields, c.radiometry);
  j["photoelectrons_per_unit"] = c.radiometry.photoelectronsPerUnit();
  return j;
}

// The axis resolved against the render, not the config's values (kBinsFields
// holds "unset" for "from the render"): by hand.
json binsJson(const InstrumentBins& bins, const TimeAxis& render) {
  const TimeAxis axis = resolveBins(bins, render);
  return {{"bin_width_s", axis.bin_width_s}, {"bin_offset_s", axis.start_s}, {"bins", axis.bins}};
}

// One overload per model: a model without one does not compile (the visit below).
json modelJson(const StreakParams& p, const TimeAxis& render) {
  json j = binsJson(p.bins, render);
  fieldsJson(j, kStreakFields, p, [&](std::string_view key) {
    if (key == "rows") j["rows"] = p.rows;
  });
  return j;
}

// The preset's name, device, each value's source and the assumed values:
// what of the sensor a reader can trace to a datasheet.
template <class Params>
json presetJson(const DevicePreset<Params>& preset) {
  json sourced = json::object(), assumed = json::object();
  for (const PresetValue& v : preset.values) {
    if (v.source) {
      sourced[v.key] = v.source;
    } else {
      assumed[v.key] = v.note;
    }
  }
  json j = {{"name", preset.name}, {"device", preset.device}};
  // The device's pixel array [width, height], where the preset gives one.
  if (preset.width > 0) j["device_image"] = {preset.width, preset.height};
  j["sourced"] = sourced;
  j["assumed"] = assumed;
  j["sources"] = std::vector<std::string>(preset.sources.begin(), preset.sources.end());
  j["note"] = "explicit config keys replace these values; the effective config has them all";
  return j;
}

json modelJson(const SpadParams& p, const TimeAxis& render) {
  json j = binsJson(p.bins, render);
  fieldsJson(j, kSpadFields, p, [&](std::string_view key) {
    if (key == "preset") {
      if (const SpadPreset* preset = findSpadPreset(p.preset)) j["preset"] = presetJson(*preset);
      return;
    }
    if (key == "irf") {
      if (!p.irf.present()) return;
      const char* t0 = p.irf.t0 == SpadIrf::TimeZero::Peak       ? "peak"
                       : p.irf.t0 == SpadIrf::TimeZero::Centroid ? "centroid"
                                                                 : "time";
      j["irf"] = {{"file", p.irf.file},
                  {"samples", p.irf.values.size()},
                  {"sample_width_s", p.irf.sample_width_s},
                  {"first_time_s", p.irf.first_time_s},
                  {"t0", t0},
                  {"time_zero_s", irfTimeZero_s(p.irf)},
                  {"floor", p.irf.floor}};
      return;
    }
    if (key == "tdc_dnl") {
      if (!p.tdc_dnl.present()) return;
      double maxAbs = 0.0;
      for (double d : p.tdc_dnl.values) maxAbs = std::max(maxAbs, std::fabs(d));
      j["tdc_dnl"] = {
          {"file", p.tdc_dnl.file}, {"bins", p.tdc_dnl.values.size()}, {"max_abs_dnl", maxAbs}};
      return;
    }
    if (key == "dark_count_map") {
      if (!p.dark_count_map.present()) return;
      j["dark_count_map"] = {{"file", p.dark_count_map.file},
                             {"shape", {p.dark_count_map.height, p.dark_count_map.width}}};
      return;
    }
    if (key == "afterpulse_delay_table") {  // as used: normalised, with its bin edges
      const SpadAfterpulseTable& t = p.afterpulse_delay_table;
      if (!t.present()) return;
      j["afterpulse_delay_table"] = {{"file", t.file},
                                     {"delays_s", t.delays_s},
                                     {"edges_s", t.edges_s},
                                     {"density_per_s", t.density_per_s}};
      return;
    }
    if (key == "afterpulse_delay") {
      if (p.afterpulse_delay_table.present()) return;  // not used
      j["afterpulse_delays_s"] = p.afterpulse_delays_s;
      return;
    }
    if (key == "afterpulse_weights") {  // as used: normalised, equal when not given
      if (p.afterpulse_delay_table.present()) return;
      std::vector<double> w = p.afterpulse_weights;
      if (w.empty()) w.assign(p.afterpulse_delays_s.size(), 1.0);
      double sum = 0.0;
      for (double x : w) sum += x;
      for (double& x : w) x /= sum;
      j["afterpulse_weights"] = w;
      return;
    }
    if (key != "plot_pixels") return;
    j["plot_pixels_xy"] = json::array();
    for (const auto& [x, y] : p.plot_pixels) j["plot_pixels_xy"].push_back({x, y});
  });
  return j;
}

// The capture as the device takes it: the order of the raws and each one's
// start time, (F, N) as the raw arrays are indexed.
json captureJson(const CwTofParams& p) {
  json order = json::array();
  for (const CwTofCaptureStep& s : cwtofCaptureOrder(p)) order.push_back({s.frequency, s.step});
  const std::vector<double> start = cwtofRawStartTimes_s(p);
  json times = json::array();
  for (std::size_t f = 0; f < p.frequencies_Hz.size(); ++f) {
    times.push_back(std::vector<double>(start.begin() + f * p.phase_steps,
                                        start.begin() + (f + 1) * p.phase_steps));
  }
  return {{"order", order},
          {"raw_start_times_s", times},
          {"doc",
           "order: [frequency index, phase step] of each raw as taken; raw_start_times_s "
           "[f][n]: its start from the first raw's, s (integration_time_s + readout_gap_s "
           "apart)"}};
}

json mapJson(const CwTofPixelMap& m) { return {{"file", m.file}, {"shape", {m.height, m.width}}}; }

json modelJson(const CwTofParams& p, const TimeAxis& render) {
  json j;
  fieldsJson(j, kCwTofFields, p, [&](std::string_view key) {
    if (key == "preset") {
      if (const CwTofPreset* preset = findCwTofPreset(p.preset)) j["preset"] = presetJson(*preset);
      return;
    }
    if (key == "delay_map" && p.delay_map.present()) j["delay_map"] = mapJson(p.delay_map);
    if (key == "gain_map" && p.gain_map.present()) j["gain_map"] = mapJson(p.gain_map);
    if (key == "offset_map" && p.offset_map.present()) j["offset_map"] = mapJson(p.offset_map);
    if (key == "companding" && p.companding.present()) {
      j["companding"] = {{"file", p.companding.file},
                         {"input_dn", p.companding.input_dn},
                         {"output_dn", p.companding.output_dn}};
    }
    if (key == "capture_order") j["capture"] = captureJson(p);
    if (key == "noise_table" && p.noise_table.present()) {
      std::size_t samples = 0, means = 0;
      for (const auto& set : p.noise_table.samples) {
        samples += set.size();
        means += !set.empty();
      }
      j["noise_table"] = {
          {"file", p.noise_table.file},
          {"first_mean_e", p.noise_table.first_mean_e},
          {"last_mean_e",
           p.noise_table.first_mean_e + static_cast<int64_t>(p.noise_table.samples.size()) - 1},
          {"means", means},
          {"samples", samples}};
    }
    if (key == "frequencies") j["frequencies_Hz"] = p.frequencies_Hz;
    if (key == "correlation" && !p.correlation.empty()) {
      // What each waveform is; its values are in the effective config.
      json list = json::array();
      for (const CorrelationWaveform& w : p.correlation) {
        list.push_back({{"form", w.fourier() ? "fourier" : "samples"},
                        {"terms", w.fourier() ? w.harmonics.size() : w.values.size()},
                        {"file", w.file},
                        {"scale", PhaseCorrelation(w).scale()}});
      }
      j["correlation"] = list;
    }
  });
  // Derived values, then colormap last, as the metadata has always been ordered.
  j.erase("colormap");
  const double k = render.depthPerSecond_m_per_s();
  j["depth_range_m"] = depthRange_m(p, k);
  json ranges = json::array();
  for (double f : p.frequencies_Hz) ranges.push_back(k / f);
  j["unambiguous_range_per_frequency_m"] = ranges;
  j["colormap"] = p.colormap;
  return j;
}
json modelJson(const ApdParams& p, const TimeAxis& render) {
  json j = binsJson(p.bins, render);
  fieldsJson(j, kApdFields, p);
  // Derived: what a datasheet quotes, and the receiver on this axis.
  const ApdReceiver rx = apdReceiver(p, render);
  if (p.common.radiometry.wavelength_m > 0.0) {
    j["responsivity_A_per_W"] = apdResponsivity_A_per_W(p.common.radiometry);
    j["responsivity_at_gain_A_per_W"] = apdResponsivity_A_per_W(p.common.radiometry) * p.gain;
  }
  j["excess_noise_factor"] = rx.excessNoise;
  j["noise_bandwidth_Hz"] = rx.noiseBandwidth_Hz;
  j["background_mean_A"] = rx.backgroundMean_A;
  j["background_sigma_A"] = rx.backgroundSigma_A;
  j["threshold_resolved_A"] = rx.threshold_A;
  return j;
}
}  // namespace

json sensorParametersJson(const SensorParams& params, const TimeAxis& render) {
  return std::visit(
      [&](const auto& p) {
        json j = commonJson(p.common);
        j.update(modelJson(p, render));
        return j;
      },
      params);
}

}  // namespace tofsim::pipeline
