#include "SensorParametersJson.h"

#include <type_traits>

#include "tofsim/sensors/Common.h"

namespace tofsim::pipeline {

namespace {
using json = nlohmann::ordered_json;
using namespace tofsim::sensors;

json commonJson(const SensorCommon& c) {
  json j;
  if (c.channel.weights.empty()) {
    j["channel"] = c.channel.index;
  } else {
    j["channel_weights"] = c.channel.weights;
  }
  const Radiometry& r = c.radiometry;
  j["source_scale"] = r.source_scale;
  j["etendue_m2sr"] = r.etendue_m2sr;
  j["optics_transmission"] = r.optics_transmission;
  j["quantum_efficiency"] = r.quantum_efficiency;
  j["wavelength_m"] = r.wavelength_m;
  j["photoelectrons_per_unit"] = r.photoelectronsPerUnit();
  return j;
}

json binsJson(const InstrumentBins& bins, const TimeAxis& render) {
  const TimeAxis axis = resolveBins(bins, render);
  return {{"bin_width_s", axis.bin_width_s}, {"bin_offset_s", axis.start_s}, {"bins", axis.bins}};
}

// One overload per model: a model without one does not compile (the visit below).
json modelJson(const StreakParams& p, const TimeAxis& render) {
  json j = binsJson(p.bins, render);
  j["rows"] = p.rows;
  j["time_fwhm_s"] = p.time_fwhm_s;
  j["spatial_fwhm_px"] = p.spatial_fwhm_px;
  j["shot_noise"] = p.shot_noise;
  j["read_noise_e"] = p.read_noise_e;
  j["gain_adu_per_e"] = p.gain_adu_per_e;
  j["saturation_adu"] = p.saturation_adu;
  j["colormap"] = p.colormap;
  return j;
}

json modelJson(const SpadParams& p, const TimeAxis& render) {
  json j = binsJson(p.bins, render);
  j["mode"] = p.mode == SpadMode::Synchronous ? "synchronous" : "free_running";
  j["cycles"] = p.cycles;
  j["pulse_fwhm_s"] = p.pulse_fwhm_s;
  j["jitter_fwhm_s"] = p.jitter_fwhm_s;
  j["jitter_tail_fraction"] = p.jitter_tail_fraction;
  j["jitter_tail_s"] = p.jitter_tail_s;
  j["pde"] = p.pde;
  j["ambient_rate_per_s"] = p.ambient_rate_per_s;
  j["dark_count_rate_per_s"] = p.dark_count_rate_per_s;
  j["dead_time_s"] = p.dead_time_s;
  j["plot_pixels_xy"] = json::array();
  for (const auto& [x, y] : p.plot_pixels) j["plot_pixels_xy"].push_back({x, y});
  j["colormap"] = p.colormap;
  return j;
}

json modelJson(const CwTofParams& p, const TimeAxis& render) {
  json j;
  j["frequencies_Hz"] = p.frequencies_Hz;
  j["phase_steps"] = p.phase_steps;
  j["waveform"] = p.waveform == Waveform::Sine ? "sine" : "square";
  j["ambient_e"] = p.ambient_e;
  j["shot_noise"] = p.shot_noise;
  j["read_noise_e"] = p.read_noise_e;
  j["max_depth_m"] = p.max_depth_m;
  j["multipath_by_order"] = p.multipath_by_order;
  const double k = render.depthPerSecond_m_per_s();
  j["depth_range_m"] = depthRange_m(p, k);
  json ranges = json::array();
  for (double f : p.frequencies_Hz) ranges.push_back(k / f);
  j["unambiguous_range_per_frequency_m"] = ranges;
  j["colormap"] = p.colormap;
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

json timeAxisJson(const TimeAxis& axis) {
  return {{"start_s", axis.start_s},
          {"bin_width_s", axis.bin_width_s},
          {"bins", axis.bins},
          {"end_s", axis.end_s()},
          {"start_m", axis.start_m()},
          {"bin_width_m", axis.bin_width_m()},
          {"depth_start_m", axis.depthOf_m(axis.start_s)},
          {"depth_bin_width_m", axis.depthOf_m(axis.bin_width_s)},
          {"index_of_refraction", axis.index_of_refraction},
          {"camera_unwarp", axis.camera_unwarp},
          {"bin_doc", "bin t covers [start_s + t * bin_width_s, start_s + (t + 1) * bin_width_s)"},
          {"length_doc",
           "*_m: optical path length c * time; depth_*: (c / index_of_refraction) * time / 2 "
           "(one leg, not / 2, with camera_unwarp), the depth of a camera with the light at it"}};
}

}  // namespace tofsim::pipeline
