#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include "ConfigNode.h"
#include "SensorConfigType.h"
#include "ShortestNumber.h"
#include "tofsim/config/SensorConfig.h"
#include "tofsim/config/Units.h"

namespace tofsim::config {

namespace {
using namespace tofsim::sensors;

std::string number(double v) { return shortest(v); }

double positive(const ConfigNode& n, const std::string& key, double value) {
  if (n.has(key) && !(value > 0.0)) n.failKey(key, "must be > 0 (got " + number(value) + ")");
  return value;
}

double nonNegative(const ConfigNode& n, const std::string& key, double value) {
  if (n.has(key) && !(value >= 0.0)) n.failKey(key, "must be >= 0 (got " + number(value) + ")");
  return value;
}

double fraction(const ConfigNode& n, const std::string& key, double value) {
  if (n.has(key) && !(value >= 0.0 && value <= 1.0)) {
    n.failKey(key, "must be in [0, 1] (got " + number(value) + ")");
  }
  return value;
}

long long positiveInt(const ConfigNode& n, const std::string& key, long long fallback,
                      long long max = 2147483647) {
  const long long v = n.getInt(key, fallback);
  if (n.has(key) && (v < 1 || v > max)) {
    n.failKey(key, "must be an integer in [1, " + std::to_string(max) + "] (got " +
                       std::to_string(v) + ")");
  }
  return v;
}

int32_t intElement(const ConfigNode& e) {
  const double v = e.asDouble();
  if (v != std::floor(v) || std::fabs(v) > 2147483647.0) e.fail("expected an integer");
  return static_cast<int32_t>(v);
}

SensorCommon parseCommon(const ConfigNode& n) {
  SensorCommon c;
  const long long channel = n.getInt("channel", 0);
  if (channel < 0) n.failKey("channel", "must be >= 0 (got " + std::to_string(channel) + ")");
  c.channel.index = static_cast<int32_t>(channel);
  if (auto w = n.optionalChild("channel_weights")) {
    for (const ConfigNode& e : w->elements()) c.channel.weights.push_back(e.asDouble());
    if (c.channel.weights.empty()) w->fail("must list one weight per volume channel");
  }
  Radiometry& r = c.radiometry;
  r.source_scale = nonNegative(n, "source_scale", n.getDouble("source_scale", r.source_scale));
  r.etendue_m2sr = positive(n, "etendue", n.getDouble("etendue", r.etendue_m2sr));
  r.optics_transmission =
      fraction(n, "optics_transmission", n.getDouble("optics_transmission", r.optics_transmission));
  r.quantum_efficiency =
      fraction(n, "quantum_efficiency", n.getDouble("quantum_efficiency", r.quantum_efficiency));
  r.wavelength_m = nonNegative(n, "wavelength", n.getLength_m("wavelength", r.wavelength_m));
  return c;
}

InstrumentBins parseBins(const ConfigNode& n) {
  InstrumentBins b;
  b.bin_width_s = positive(n, "bin_width", n.getDuration_s("bin_width", b.bin_width_s));
  if (n.has("bin_offset")) b.offset_s = n.getDuration_s("bin_offset", 0.0);
  b.count = static_cast<int32_t>(positiveInt(n, "bins", b.count));
  return b;
}

}  // namespace

// --- streak ---------------------------------------------------------------------
StreakParams SensorConfigType<StreakParams>::parse(const ConfigNode& n) {
  StreakParams p;
  p.common = parseCommon(n);
  p.bins = parseBins(n);
  if (auto rows = n.optionalChild("rows")) {
    for (const ConfigNode& e : rows->elements()) {
      p.rows.push_back(intElement(e));
      if (p.rows.back() < 0) e.fail("row must be >= 0");
    }
  }
  p.time_fwhm_s = nonNegative(n, "time_fwhm", n.getDuration_s("time_fwhm", p.time_fwhm_s));
  p.spatial_fwhm_px =
      nonNegative(n, "spatial_fwhm", n.getDouble("spatial_fwhm", p.spatial_fwhm_px));
  p.shot_noise = n.getBool("shot_noise", p.shot_noise);
  p.read_noise_e = nonNegative(n, "read_noise", n.getDouble("read_noise", p.read_noise_e));
  p.gain_adu_per_e = positive(n, "gain", n.getDouble("gain", p.gain_adu_per_e));
  p.saturation_adu = positive(n, "saturation", n.getDouble("saturation", p.saturation_adu));
  p.colormap = n.getString("colormap", p.colormap);
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

// --- spad -----------------------------------------------------------------------
SpadParams SensorConfigType<SpadParams>::parse(const ConfigNode& n) {
  SpadParams p;
  p.common = parseCommon(n);
  p.bins = parseBins(n);
  const std::string mode = n.getString("mode", "synchronous");
  if (mode == "synchronous") {
    p.mode = SpadMode::Synchronous;
  } else if (mode == "free_running") {
    p.mode = SpadMode::FreeRunning;
  } else {
    n.failKey("mode", "must be synchronous or free_running (got '" + mode + "')");
  }
  p.cycles = positiveInt(n, "cycles", p.cycles, 1'000'000'000'000LL);
  p.pulse_fwhm_s = nonNegative(n, "pulse_fwhm", n.getDuration_s("pulse_fwhm", p.pulse_fwhm_s));
  p.jitter_fwhm_s = nonNegative(n, "jitter_fwhm", n.getDuration_s("jitter_fwhm", p.jitter_fwhm_s));
  p.jitter_tail_fraction = fraction(n, "jitter_tail_fraction",
                                    n.getDouble("jitter_tail_fraction", p.jitter_tail_fraction));
  p.jitter_tail_s = nonNegative(n, "jitter_tail", n.getDuration_s("jitter_tail", p.jitter_tail_s));
  p.pde = fraction(n, "pde", n.getDouble("pde", p.pde));
  p.ambient_rate_per_s =
      nonNegative(n, "ambient_rate", n.getFrequency_Hz("ambient_rate", p.ambient_rate_per_s));
  p.dark_count_rate_per_s = nonNegative(
      n, "dark_count_rate", n.getFrequency_Hz("dark_count_rate", p.dark_count_rate_per_s));
  p.dead_time_s = nonNegative(n, "dead_time", n.getDuration_s("dead_time", p.dead_time_s));
  if (auto pixels = n.optionalChild("plot_pixels")) {
    for (const ConfigNode& e : pixels->elements()) {
      if (!e.isSequence() || e.yaml().size() != 2) e.fail("expected [x, y]");
      const std::vector<ConfigNode> xy = e.elements();
      p.plot_pixels.push_back({intElement(xy[0]), intElement(xy[1])});
    }
  }
  p.colormap = n.getString("colormap", p.colormap);
  return p;
}

void SensorConfigType<SpadParams>::checkImage(const ConfigNode& n, const SpadParams& p,
                                              const capture::Camera& camera) {
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
  p.common = parseCommon(n);
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
  p.phase_steps = static_cast<int32_t>(positiveInt(n, "phase_steps", p.phase_steps, 1024));
  if (p.phase_steps < 3) n.failKey("phase_steps", "must be >= 3");
  const std::string waveform = n.getString("waveform", "sine");
  if (waveform == "sine") {
    p.waveform = Waveform::Sine;
  } else if (waveform == "square") {
    p.waveform = Waveform::Square;
  } else {
    n.failKey("waveform", "must be sine or square (got '" + waveform + "')");
  }
  p.ambient_e = nonNegative(n, "ambient", n.getDouble("ambient", p.ambient_e));
  p.shot_noise = n.getBool("shot_noise", p.shot_noise);
  p.read_noise_e = nonNegative(n, "read_noise", n.getDouble("read_noise", p.read_noise_e));
  p.max_depth_m = nonNegative(n, "max_depth", n.getLength_m("max_depth", p.max_depth_m));
  p.colormap = n.getString("colormap", p.colormap);
  p.multipath_by_order = n.getBool("multipath_by_order", p.multipath_by_order);
  return p;
}

void SensorConfigType<CwTofParams>::checkImage(const ConfigNode&, const CwTofParams&,
                                               const capture::Camera&) {}  // every pixel, no rows

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
    n.reportUnusedKeys();
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

}  // namespace tofsim::config
