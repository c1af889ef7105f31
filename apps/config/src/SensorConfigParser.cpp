#include <cmath>
#include <cstdio>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

#include "ConfigNode.h"
#include "CwTofCaptureOrderConfig.h"
#include "CwTofDeviceConfig.h"
#include "CwTofWaveformFile.h"
#include "FieldParse.h"
#include "IrfFile.h"
#include "SensorConfigType.h"
#include "SpadTableFile.h"
#include "tofsim/config/ConfigKeys.h"
#include "tofsim/config/SensorConfig.h"
#include "tofsim/config/Units.h"
#include "tofsim/sensors/CwTofPresets.h"
#include "tofsim/sensors/SensorFields.h"
#include "tofsim/sensors/SensorType.h"
#include "tofsim/sensors/SpadPresets.h"

namespace tofsim::config {

namespace {
using namespace tofsim::sensors;

int32_t intElement(const ConfigNode& e) {
  const double v = e.asDouble();
  if (v != std::floor(v) || std::fabs(v) > 2147483647.0) e.fail("expected an integer");
  return static_cast<int32_t>(v);
}

// `c`: the model's defaults (an APD's radiometry is not a camera's).
SensorCommon parseCommon(const ConfigNode& n, SensorCommon c = {}) {
  // `channel` or `channel_weights`: one choice of two keys, by hand.
  // Neither given: the sum of the channels (ChannelSelection's default).
  if (n.has("channel")) {
    const long long channel = n.getInt("channel", 0);
    if (channel < 0) n.failKey("channel", "must be >= 0 (got " + std::to_string(channel) + ")");
    c.channel.index = static_cast<int32_t>(channel);
  }
  if (auto w = n.optionalChild("channel_weights")) {
    for (const ConfigNode& e : w->elements()) c.channel.weights.push_back(e.asDouble());
    if (c.channel.weights.empty()) w->fail("must list one weight per volume channel");
  }
  parseFields(n, kRadiometryFields, c.radiometry);
  return c;
}

InstrumentBins parseBins(const ConfigNode& n, InstrumentBins b = {}) {
  parseFields(n, kBinsFields, b);
  return b;
}

}  // namespace

// --- streak ---------------------------------------------------------------------
StreakParams SensorConfigType<StreakParams>::parse(const ConfigNode& n) {
  StreakParams p;
  p.common = parseCommon(n);
  p.bins = parseBins(n);
  parseFields(n, kStreakFields, p, [&](std::string_view key) {
    if (key != "rows") return;
    if (auto rows = n.optionalChild("rows")) {  // a list: by hand
      for (const ConfigNode& e : rows->elements()) {
        p.rows.push_back(intElement(e));
        if (p.rows.back() < 0) e.fail("row must be >= 0");
      }
    }
  });
  return p;
}

void SensorConfigType<StreakParams>::checkImage(const ConfigNode& n, const StreakParams& p,
                                                const capture::Camera& camera) {
  for (int32_t row : p.rows) {
    if (row >= camera.height) {
      n.failKey("rows", "row " + std::to_string(row) + " is outside the image (height " +
                            std::to_string(camera.height) + ")");
    }
  }
}

namespace {
// `preset:` first: its values are the defaults the keys below replace.
// `model` names the sensor type in the error ("SPAD", "CW-ToF").
template <class Params>
void applyPreset(const ConfigNode& n, std::span<const DevicePreset<Params>> presets,
                 const char* model, Params& p) {
  if (!n.has("preset")) return;
  const std::string name = n.getString("preset", "");
  const DevicePreset<Params>* preset = findPreset(presets, name);
  if (!preset) {
    std::string known;
    for (const DevicePreset<Params>& s : presets)
      known += (known.empty() ? "" : ", ") + std::string(s.name);
    n.failKey("preset",
              "unknown " + std::string(model) + " preset '" + name + "' (known: " + known + ")");
  }
  preset->apply(p);
  p.preset = name;
}
}  // namespace

// --- spad -----------------------------------------------------------------------
namespace {

// The gate's transitions and skew shape a gate, the frame keys the gated
// frames: without them they are typos.
void checkGateShape(const ConfigNode& n, const SpadParams& p) {
  for (const auto& [key, value] :
       {std::pair{"gate_rise", p.gate_rise_s}, std::pair{"gate_fall", p.gate_fall_s},
        std::pair{"gate_skew_sigma", p.gate_skew_sigma_s}}) {
    if (value > 0.0 && !(p.gate_width_s > 0.0)) {
      n.failKey(key, "shapes the gate: set `gate_width` (> 0) too");
    }
  }
  if (p.gated_frames > 0 && !(p.gate_width_s > 0.0)) {
    n.failKey("gated_frames", "gated frames need a gate: set `gate_width` (> 0) too");
  }
  // By value, not presence: the effective config writes every key.
  for (const auto& [key, set] : {std::pair{"pulses_per_frame", p.pulses_per_frame != 1},
                                 std::pair{"gate_step", p.gate_step_s != 0.0},
                                 std::pair{"gate_positions", p.gate_positions != 1}}) {
    if (p.gated_frames == 0 && set) {
      n.failKey(key, "shapes the gated 1-bit frames: set `gated_frames` (> 0) too");
    }
  }
  if (p.gate_width_s > 0.0 && p.gate_width_s < 0.5 * (p.gate_rise_s + p.gate_fall_s)) {
    n.failKey(n.has("gate_rise") ? "gate_rise" : "gate_fall",
              "the gate's ramps overlap: gate_width (" + durationText(p.gate_width_s) +
                  ") must be >= (gate_rise + gate_fall) / 2 (" +
                  durationText(0.5 * (p.gate_rise_s + p.gate_fall_s)) + ")");
  }
}

// Crosstalk's neighbours send what they detect inside their own gate: with
// ramps or per-pixel skew a receiver's armed times differ from its
// neighbour's (the bin averages of one gate do not give the product of two),
// which the first-order path (`engine: fast`) cannot follow; the exact array
// driver (`auto`, `exact`) takes each arrival with the receiver's own gate.
// The gated frames' other gate positions get no crosstalk at all. Those
// combinations are refused rather than drawn wrong.
void checkCrosstalkGate(const ConfigNode& n, const SpadParams& p) {
  if (!(p.crosstalk_probability > 0.0)) return;
  if (p.gated_frames > 0) {
    n.failKey("gated_frames",
              "crosstalk (crosstalk_probability) with `gated_frames` is not modelled: use "
              "gated frames without crosstalk, or crosstalk without gated frames");
  }
  if (p.engine != SpadEngine::Fast) return;
  for (const auto& [key, set] :
       {std::pair{"gate_rise", p.gate_rise_s > 0.0}, std::pair{"gate_fall", p.gate_fall_s > 0.0},
        std::pair{"gate_skew_sigma", p.gate_skew_sigma_s > 0.0}}) {
    if (set) {
      n.failKey(key, std::string("crosstalk (crosstalk_probability) with `") + key +
                         "` is not modelled by `engine: fast` (first order): use `engine: "
                         "auto` or `exact`, a hard, unskewed gate, or no crosstalk");
    }
  }
}

// `afterpulse_delay` (a duration or a list: the mixture's means) and
// `afterpulse_weights` (numbers), each element with its own located error.
void parseAfterpulseList(const ConfigNode& n, std::string_view key, SpadParams& p) {
  const auto list = n.optionalChild(std::string(key));
  if (!list) return;
  const bool delays = key == "afterpulse_delay";
  std::vector<double>& out = delays ? p.afterpulse_delays_s : p.afterpulse_weights;
  out.clear();
  for (const ConfigNode& e : list->isSequence() ? list->elements() : std::vector{*list}) {
    const double v = delays ? e.asDuration_s() : e.asDouble();
    if (delays && !(v > 0.0)) e.fail("delay must be > 0 (got " + e.asString() + ")");
    if (!delays && !(v >= 0.0)) e.fail("weight must be >= 0 (got " + e.asString() + ")");
    out.push_back(v);
  }
  if (out.empty()) list->fail("must list at least one value");
}

// The afterpulse keys that must agree, and the ones that mean nothing
// without afterpulses.
void checkAfterpulses(const ConfigNode& n, const SpadParams& p) {
  const std::size_t delays = p.afterpulse_delays_s.size(), weights = p.afterpulse_weights.size();
  if (weights > 0 && weights != delays) {
    n.failKey("afterpulse_weights", "gives " + std::to_string(weights) + " weights for " +
                                        std::to_string(delays) + " afterpulse_delay means");
  }
  if (weights > 0) {
    double sum = 0.0;
    for (double w : p.afterpulse_weights) sum += w;
    if (!(sum > 0.0)) n.failKey("afterpulse_weights", "must not all be 0");
  }
  if (p.afterpulse_probability > 0.0) return;
  const char* without = nullptr;
  if (p.afterpulse_count != SpadAfterpulseCount::Bernoulli) without = "afterpulse_count";
  if (p.afterpulse_traps != SpadAfterpulseTraps::Reset) without = "afterpulse_traps";
  if (weights > 0) without = "afterpulse_weights";
  if (p.afterpulse_delay_table.present()) without = "afterpulse_delay_table";
  if (without) n.failKey(without, "has no effect while afterpulse_probability is 0");
}
}  // namespace

SpadParams SensorConfigType<SpadParams>::parse(const ConfigNode& n) {
  SpadParams p;
  applyPreset(n, spadPresets(), "SPAD", p);
  p.common = parseCommon(n);
  p.bins = parseBins(n, p.bins);
  parseFields(n, kSpadFields, p, [&](std::string_view key) {
    if (key == "irf") {
      const auto irf = n.optionalChild("irf");
      if (!irf) return;
      // Read before `irf` (table order); 0 is what the effective config writes.
      const std::pair<const char*, double> replacedValues[] = {
          {"pulse_fwhm", p.pulse_fwhm_s},
          {"jitter_fwhm", p.jitter_fwhm_s},
          {"jitter_tail_fraction", p.jitter_tail_fraction}};
      for (const auto& [replaced, value] : replacedValues) {
        if (value != 0.0 && n.has(replaced)) {
          n.failKey(replaced, "`irf` replaces pulse_fwhm, jitter_fwhm and jitter_tail_*: remove `" +
                                  std::string(replaced) + "`");
        }
      }
      // A preset's pulse and jitter are defaults: the explicit `irf` wins.
      p.pulse_fwhm_s = p.jitter_fwhm_s = p.jitter_tail_fraction = 0.0;
      p.irf = parseIrf(*irf);
      return;
    }
    if (key == "tdc_dnl") {
      if (n.has("tdc_dnl")) p.tdc_dnl = parseDnl(n);
      return;
    }
    if (key == "dark_count_map") {
      if (n.has("dark_count_map")) p.dark_count_map = parseDarkCountMap(n);
      return;
    }
    if (key == "afterpulse_delay" || key == "afterpulse_weights") {
      parseAfterpulseList(n, key, p);
      return;
    }
    if (key == "afterpulse_delay_table") {
      if (!n.has(key.data())) return;
      // A preset's exponentials are defaults: the explicit table wins.
      for (const char* mixture : {"afterpulse_delay", "afterpulse_weights"}) {
        if (n.has(mixture)) {
          n.failKey(mixture, "`afterpulse_delay_table` gives the delays: remove `" +
                                 std::string(mixture) + "` (or the table)");
        }
      }
      p.afterpulse_delay_table = parseAfterpulseDelayTable(n);
      p.afterpulse_weights.clear();
      return;
    }
    if (key != "plot_pixels") return;
    if (auto pixels = n.optionalChild("plot_pixels")) {  // a list of pairs: by hand
      for (const ConfigNode& e : pixels->elements()) {
        if (!e.isSequence() || e.yaml().size() != 2) e.fail("expected [x, y]");
        const std::vector<ConfigNode> xy = e.elements();
        p.plot_pixels.push_back({intElement(xy[0]), intElement(xy[1])});
      }
    }
  });
  checkAfterpulses(n, p);
  if (p.mode == SpadMode::FreeRunning && p.tdc_stops != 1) {
    n.failKey("tdc_stops", "is for `mode: synchronous` (free_running records every detection)");
  }
  if (p.hot_pixel_fraction > 0.0 && !(p.hot_pixel_rate_per_s > 0.0)) {
    n.failKey("hot_pixel_rate", "must be > 0 when hot_pixel_fraction is set");
  }
  checkGateShape(n, p);
  if (p.dark_count_map.present() && p.dark_count_log_sigma > 0.0) {
    n.failKey("dark_count_log_sigma",
              "the measured `dark_count_map` replaces the log-normal draw: remove it");
  }
  // A delayed arrival may land outside the gate, which the first-order path
  // does not follow (the exact array driver does).
  if (p.crosstalk_probability > 0.0 && p.crosstalk_delay_s > 0.0 && p.gate_width_s > 0.0 &&
      p.engine == SpadEngine::Fast) {
    n.failKey("crosstalk_delay",
              "delayed crosstalk with a gate (gate_width) is not modelled by `engine: fast` "
              "(first order): use `engine: auto` or `exact`, prompt crosstalk (0) or no gate");
  }
  checkCrosstalkGate(n, p);
  return p;
}

void SensorConfigType<SpadParams>::checkImage(const ConfigNode& n, const SpadParams& p,
                                              const capture::Camera& camera) {
  const SpadDarkCountMap& map = p.dark_count_map;
  if (map.present() && (map.height != camera.height || map.width != camera.width)) {
    n.failKey("dark_count_map", map.file + " is " + std::to_string(map.height) + " x " +
                                    std::to_string(map.width) + " (H x W) but the image is " +
                                    std::to_string(camera.height) + " x " +
                                    std::to_string(camera.width));
  }
  for (const auto& xy : p.plot_pixels) {
    if (xy[0] < 0 || xy[1] < 0 || xy[0] >= camera.width || xy[1] >= camera.height) {
      n.failKey("plot_pixels", "pixel (" + std::to_string(xy[0]) + ", " + std::to_string(xy[1]) +
                                   ") is outside the " + std::to_string(camera.width) + "x" +
                                   std::to_string(camera.height) + " image");
    }
  }
}

// --- cwtof ----------------------------------------------------------------------
CwTofParams SensorConfigType<CwTofParams>::parse(const ConfigNode& n) {
  CwTofParams p;
  applyPreset(n, cwtofPresets(), "CW-ToF", p);
  p.common = parseCommon(n);
  parseFields(n, kCwTofFields, p, [&](std::string_view key) {
    if (parseCwTofDeviceKey(n, key, p)) return;
    if (key == "correlation") {  // after `frequencies` and `waveform` (table order)
      const bool measured = p.waveform == Waveform::Measured;
      if (n.has("correlation") && !measured) {
        n.failKey("correlation", "is the waveform of `waveform: measured`: set it, or remove this");
      }
      if (measured && !n.has("correlation")) {
        n.failKey("waveform", "`measured` needs `correlation` (the measured waveform)");
      }
      if (measured) p.correlation = parseCorrelation(n, p.frequencies_Hz.size());
      return;
    }
    if (key != "frequencies") return;
    // A frequency or a list of them, each with its own located error: by hand.
    if (auto freqs = n.optionalChild("frequencies")) {
      p.frequencies_Hz.clear();
      const std::vector<ConfigNode> list =
          freqs->isSequence() ? freqs->elements() : std::vector<ConfigNode>{*freqs};
      for (const ConfigNode& e : list) {
        double f = 0.0;
        try {
          f = parseFrequency_Hz(e.asString());
        } catch (const std::invalid_argument& err) {
          e.fail(err.what());
        }
        if (!(f > 0.0)) e.fail("frequency must be > 0 (got " + e.asString() + ")");
        p.frequencies_Hz.push_back(f);
      }
      if (p.frequencies_Hz.empty()) freqs->fail("must list at least one frequency");
    }
  });
  derivePresetCaptureOrder(n, p);
  checkCwTofDevice(n, p);
  return p;
}

void SensorConfigType<CwTofParams>::checkImage(const ConfigNode& n, const CwTofParams& p,
                                               const capture::Camera& camera) {
  checkCwTofMapsFitImage(n, p, camera);
}

// --- apd ------------------------------------------------------------------------
ApdParams SensorConfigType<ApdParams>::parse(const ConfigNode& n) {
  ApdParams p;
  p.common = parseCommon(n, p.common);
  p.bins = parseBins(n);
  parseFields(n, kApdFields, p);
  if (p.threshold_mode == ApdThreshold::Fixed && !n.has("threshold")) {
    n.failKey("threshold_mode", "`fixed` needs `threshold` (a current, A)");
  }
  return p;
}

void SensorConfigType<ApdParams>::checkImage(const ConfigNode&, const ApdParams&,
                                             const capture::Camera&) {}

namespace {
// The `type:` names in variant order, for the error that lists them.
template <std::size_t... I>
std::string knownTypes(std::index_sequence<I...>) {
  std::string known;
  ((known +=
    (I ? ", " : "") + std::string(SensorType<std::variant_alternative_t<I, SensorParams>>::name)),
   ...);
  return known;
}

// A key this sensor type does not take but another one does is a mix-up of
// types, not a typo: "'frequencies' is a cwtof key; this sensor is a spad".
// The model rows of sensorConfigKeys() are "<type>.<key>".
std::string otherTypesKey(const std::string& type, const std::string& key) {
  if (key.find_first_of(".[") != std::string::npos) return "";
  std::string owners;
  for (const ConfigKey& row : sensorConfigKeys()) {
    const std::string path = row.path;
    const std::size_t dot = path.find('.');
    const std::string model = path.substr(0, dot);
    if (path.substr(dot + 1) != key) continue;
    if (model == type || model == "common" || model == "bins") return "";
    if (owners.find(model) == std::string::npos) owners += (owners.empty() ? "" : " and ") + model;
  }
  if (owners.empty()) return "";
  return "'" + key + "' is a " + owners + " key; this sensor is a " + type;
}

/// Parses the alternative whose SensorType<>::name is `type`; false for none.
template <std::size_t I = 0>
bool parseAs(const std::string& type, const ConfigNode& n, SensorParams& out) {
  if constexpr (I < std::variant_size_v<SensorParams>) {
    using P = std::variant_alternative_t<I, SensorParams>;
    if (type == SensorType<P>::name) {
      out = SensorConfigType<P>::parse(n);
      return true;
    }
    return parseAs<I + 1>(type, n, out);
  }
  return false;
}
}  // namespace

std::vector<SensorSpec> parseSensors(const ConfigNode& list) {
  std::vector<SensorSpec> specs;
  for (const ConfigNode& n : list.elements()) {
    if (!n.isMap()) n.fail("expected a mapping with a `type` key");
    const std::string type = n.requireString("type");
    SensorSpec spec;
    if (!parseAs(type, n, spec.params)) {
      n.failKey("type",
                "unknown sensor type '" + type + "' (known: " +
                    knownTypes(std::make_index_sequence<std::variant_size_v<SensorParams>>()) +
                    ")");
    }
    spec.name = n.getString("name", type);
    n.reportUnusedKeys([&](const std::string& key) { return otherTypesKey(type, key); });
    specs.push_back(std::move(spec));
  }
  return specs;
}

void checkSensorsFitImage(const ConfigNode& list, const std::vector<SensorSpec>& specs,
                          const capture::Camera& camera) {
  const std::vector<ConfigNode> nodes = list.elements();
  for (std::size_t i = 0; i < specs.size() && i < nodes.size(); ++i) {
    std::visit(
        [&](const auto& p) {
          SensorConfigType<std::decay_t<decltype(p)>>::checkImage(nodes[i], p, camera);
        },
        specs[i].params);
  }
}

void checkSensorKernels(const ConfigNode& list, const std::vector<SensorSpec>& specs,
                        const TimeAxis& render) {
  const std::vector<ConfigNode> nodes = list.elements();
  for (std::size_t i = 0; i < specs.size() && i < nodes.size(); ++i) {
    const std::vector<TimeKernelUse> kernels = std::visit(
        [&](const auto& p) {
          return SensorType<std::decay_t<decltype(p)>>::timeKernels(p, render);
        },
        specs[i].params);
    for (const TimeKernelUse& k : kernels) {
      const std::string problem = timeKernelProblem(k);
      if (problem.empty()) continue;
      if (std::string_view(k.key) == "irf") {
        const auto* spad = std::get_if<SpadParams>(&specs[i].params);
        nodes[i].child("irf").failKey(
            "file", (spad ? spad->irf.file + ": " : std::string()) + "the response (" +
                        std::to_string(spad ? spad->irf.values.size() : 0) + " samples " +
                        (spad ? durationText(spad->irf.sample_width_s) : "") + " apart) " +
                        problem);
      }
      nodes[i].failKey(k.key, problem);
    }
  }
}

}  // namespace tofsim::config
