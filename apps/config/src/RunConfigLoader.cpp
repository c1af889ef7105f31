#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <variant>

#include "CameraConfigParser.h"
#include "ConfigNode.h"
#include "FieldParse.h"
#include "NlosConfigParser.h"
#include "RunConfigYaml.h"
#include "RunFields.h"
#include "SequenceConfigParser.h"
#include "SpadTableFile.h"
#include "ShortestNumber.h"
#include "Vec3Key.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/config/SensorConfig.h"
#include "tofsim/sensors/Common.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::config {

const char* irBackendName(IrBackendKind kind) {
  switch (kind) {
    case IrBackendKind::Gl:
      return "gl";
    case IrBackendKind::Cpu:
      return "cpu";
    case IrBackendKind::Auto:
      break;
  }
  return "auto";
}

namespace {

long long intInRange(const ConfigNode& node, const std::string& key, long long fallback,
                     long long lo, long long hi) {
  const long long v = node.getInt(key, fallback);
  if (v < lo || v > hi) {
    node.failKey(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " +
                          std::to_string(v) + ")");
  }
  return v;
}

void requirePositive(const ConfigNode& node, const std::string& key, double value) {
  if (!(value > 0.0)) node.failKey(key, "must be > 0 (got " + shortest(value) + ")");
}

void parseLight(const ConfigNode& node, LightConfig& out) {
  capture::Light& l = out.light;
  const std::string type = node.getString("type", "point");
  if (type == "point") {
    l.type = capture::Light::Type::Point;
  } else if (type == "spot") {
    l.type = capture::Light::Type::Spot;
  } else {
    node.failKey("type", "must be point or spot (got '" + type + "')");
  }
  out.attach_to_camera = node.getBool("attach_to_camera", false);
  out.offset_camera_m = vec3Of(node, "offset", out.offset_camera_m);
  l.position_world = vec3Of(node, "position", l.position_world);
  l.direction_world = vec3Of(node, "direction", l.direction_world);
  if (glm::length(l.direction_world) <= 0.0f) node.failKey("direction", "must not be zero");
  l.direction_world = glm::normalize(l.direction_world);
  l.cone_half_angle_deg =
      static_cast<float>(node.getAngle_deg("cone_angle", l.cone_half_angle_deg));
  if (!(l.cone_half_angle_deg > 0.0f && l.cone_half_angle_deg <= 180.0f)) {
    node.failKey("cone_angle", "half angle must be in (0, 180] degrees");
  }
  l.cone_falloff_deg = static_cast<float>(node.getAngle_deg("cone_falloff", l.cone_falloff_deg));
  if (!(l.cone_falloff_deg >= 0.0f && l.cone_falloff_deg <= l.cone_half_angle_deg)) {
    node.failKey("cone_falloff", "must be in [0, cone_angle]");
  }
  if (node.has("intensity") && node.child("intensity").isScalar()) {
    const double i = node.getDouble("intensity", 1.0);
    l.intensity_W_per_sr = glm::vec3(static_cast<float>(i));
  } else {
    l.intensity_W_per_sr = vec3Of(node, "intensity", l.intensity_W_per_sr);
  }
  for (int c = 0; c < 3; ++c) {
    if (!(l.intensity_W_per_sr[c] >= 0.0f)) node.failKey("intensity", "must be >= 0 W/sr");
  }
}

void parseTime(const ConfigNode& node, capture::RenderSettings& r) {
  r.time.start_s = node.getDuration_s("start", 0.0);
  r.time.bin_width_s = node.getDuration_s("bin_width", 10e-12);
  requirePositive(node, "bin_width", r.time.bin_width_s);
  r.time.bins = static_cast<int32_t>(intInRange(node, "bins", 512, 1, 1 << 20));
  // One place for both: the renderers and the sensors (depth = (c / eta) t /
  // legs) read the axis's.
  r.time.index_of_refraction = node.getDouble("index_of_refraction", 1.0);
  if (!(r.time.index_of_refraction >= 1.0)) node.failKey("index_of_refraction", "must be >= 1");
  r.time.camera_unwarp = node.getBool("camera_unwarp", false);
}

void parseIndirect(const ConfigNode& node, capture::IndirectSettings& s) {
  parseFields(node, kIndirectFields, s);
}

// render.renderer and render.backend.
void parseRendererChoice(const ConfigNode& node, RunConfig& out) {
  const std::string renderer = node.getString("renderer", "ir");
  if (renderer == "ir") {
    out.renderer = RendererKind::InstantRadiosity;
  } else if (renderer == "reference") {
    out.renderer = RendererKind::Reference;
  } else {
    node.failKey("renderer", "must be ir or reference (got '" + renderer + "')");
  }
  const std::string backend = node.getString("backend", "auto");
  if (backend == "auto") {
    out.backend = IrBackendKind::Auto;
  } else if (backend == "gl") {
    out.backend = IrBackendKind::Gl;
  } else if (backend == "cpu") {
    out.backend = IrBackendKind::Cpu;
  } else {
    node.failKey("backend", "must be auto, gl or cpu (got '" + backend + "')");
  }
}

void parseRender(const ConfigNode& node, RunConfig& out) {
  parseRendererChoice(node, out);
  out.strict = node.getBool("strict", out.strict);
  out.cpu_threads = static_cast<int32_t>(intInRange(node, "threads", out.cpu_threads, 0, 4096));
  capture::RenderSettings& r = out.render;
  r.seed = static_cast<uint64_t>(intInRange(node, "seed", 1, 0, (1LL << 62)));
  r.shadow_map_resolution = static_cast<int32_t>(
      intInRange(node, "shadow_map_resolution", r.shadow_map_resolution, 16, 16384));
  const double budget = node.getBytes("memory_budget", static_cast<double>(r.memory_budget_bytes));
  // The upper bound keeps the conversion to size_t defined (found by fuzz_config).
  constexpr double kMaxBudget = 0x1p50;  // 1 PiB
  if (!(budget >= 1024.0 * 1024.0 && budget <= kMaxBudget)) {
    node.failKey("memory_budget", "must be between 1 MiB and 1 PiB");
  }
  r.memory_budget_bytes = static_cast<std::size_t>(budget);
  r.pixel_footprint = node.getBool("pixel_footprint", r.pixel_footprint);
  r.pixel_samples = static_cast<int32_t>(intInRange(node, "pixel_samples", r.pixel_samples, 1, 16));
  r.adaptive_pixel_samples = node.getBool("adaptive_pixel_samples", r.adaptive_pixel_samples);
  const std::string materials = node.getString("materials", "lambertian");
  if (materials == "lambertian" || materials == "gltf") {
    r.materials =
        materials == "gltf" ? capture::MaterialModel::Gltf : capture::MaterialModel::Lambertian;
  } else {
    node.failKey("materials", "must be lambertian or gltf (got '" + materials + "')");
  }
  if (const auto indirect = node.optionalChild("indirect")) parseIndirect(*indirect, r.indirect);
  if (const auto reference = node.optionalChild("reference")) {
    parseFields(*reference, kReferenceFields, out.reference);
  }
}

// "bounce<k>" with 1 <= k <= the IR renderer's render.indirect.bounces.
void parseBounceComponent(const ConfigNode& c, const std::string& name, const RunConfig& config,
                          OutputConfig& o) {
  const std::string digits = name.substr(6);
  const bool number = !digits.empty() && digits.size() <= 2 && digits[0] != '0' &&
                      digits.find_first_not_of("0123456789") == std::string::npos;
  const int32_t bounces = config.render.indirect.bounces;
  if (!number || std::stoi(digits) > bounces) {
    c.fail("'" + name + "': bounce components are bounce1 .. bounce" + std::to_string(bounces) +
           " (render.indirect.bounces: " + std::to_string(bounces) + ")");
  }
  if (config.renderer != RendererKind::InstantRadiosity) {
    c.fail("'" + name + "': bounce components come from the IR renderer (render.renderer: ir)");
  }
  const int32_t k = std::stoi(digits);
  if (std::find(o.bounces.begin(), o.bounces.end(), k) == o.bounces.end()) o.bounces.push_back(k);
  std::sort(o.bounces.begin(), o.bounces.end());
}

void parseOutput(const ConfigNode& node, const RunConfig& config, OutputConfig& o) {
  o.directory = node.getString("directory", o.directory.string());
  parseFields(node, kOutputFields, o);
  o.transient = node.getBool("transient", o.transient);
  o.steady = node.getBool("steady", o.steady);
  o.depth = node.getBool("depth", o.depth);
  o.frames = node.getBool("frames", o.frames);
  o.video = node.getBool("video", o.video);
  o.frame_pngs = node.getBool("frame_pngs", o.frame_pngs);
  const std::string toneMap = node.getString("video_tone_map", "global");
  if (toneMap == "global") {
    o.video_tone_map = VideoToneMap::Global;
  } else if (toneMap == "log") {
    o.video_tone_map = VideoToneMap::Log;
  } else {
    node.failKey("video_tone_map", "must be global or log (got '" + toneMap + "')");
  }
  o.video_stride =
      static_cast<int32_t>(intInRange(node, "video_stride", o.video_stride, 1, 1 << 20));
  o.video_window =
      static_cast<int32_t>(intInRange(node, "video_window", o.video_window, 1, 1 << 20));
  o.video_fps = node.getDouble("video_fps", o.video_fps);
  requirePositive(node, "video_fps", o.video_fps);
  const double maxBytes = node.getBytes("max_bytes", static_cast<double>(o.max_bytes));
  constexpr double kMaxOutputBytes = 0x1p60;  // 1 EiB: keeps the conversion defined
  if (!(maxBytes >= 1.0 && maxBytes <= kMaxOutputBytes)) {
    node.failKey("max_bytes", "must be between 1 B and 1 EiB");
  }
  o.max_bytes = static_cast<std::uintmax_t>(maxBytes);
  if (const auto ranges = node.optionalChild("plot_ranges")) {
    if (!ranges->isMap()) {
      ranges->fail("expected a mapping of picture name -> [lo, hi]");
    }
    for (const std::string& name : ranges->keys()) {
      // A key without a value (`depth:`) is listed but not `has` (found by
      // fuzz_sequence: r[0] of no values).
      if (!ranges->has(name)) ranges->failKey(name, "must be [lo, hi] with lo < hi (got nothing)");
      const std::vector<double> r = ranges->getDoubles(name, 2, {});
      if (!(std::isfinite(r[0]) && std::isfinite(r[1]) && r[0] < r[1])) {
        ranges->failKey(name, "must be [lo, hi] with lo < hi");
      }
      o.plot_ranges[name] = {r[0], r[1]};
    }
  }
  if (const auto components = node.optionalChild("components")) {
    for (const ConfigNode& c : components->elements()) {
      const std::string name = c.asString();
      if (name == "direct") {
        o.direct = true;
      } else if (name == "indirect") {
        o.indirect = true;
      } else if (name.rfind("bounce", 0) == 0) {
        parseBounceComponent(c, name, config, o);
      } else {
        c.fail("components are direct, indirect and bounce1 .. bounceN (got '" + name + "')");
      }
    }
  }
}

// Sensor names become folder names (OUTDIR/sensors/<name>/): keep them plain
// and unique, so two sensors never write into the same place.
void checkSensorNames(const ConfigNode& list, const std::vector<sensors::SensorSpec>& specs) {
  const std::vector<ConfigNode> elements = list.elements();
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const std::string& name = specs[i].name;
    const bool plain = !name.empty() && name != "." && name != ".." &&
                       name.find_first_not_of(
                           "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                           "0123456789_.-") == std::string::npos;
    if (!plain) {
      elements[i].failKey("name", "must be letters, digits, '_', '-' or '.' (got '" + name + "')");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (specs[j].name == name) {
        elements[i].failKey("name", "sensor name '" + name + "' is already used by sensors[" +
                                        std::to_string(j) + "]; give each sensor its own `name`");
      }
    }
  }
}

// A CW-ToF sensor's error by bounce order compares with the ground-truth
// depth, and needs the light split by bounce: the IR renderer's bounce
// components, or the reference's direct and indirect light when that is one
// bounce at most (render.reference.bounces <= 2).
void checkBounceOrders(const ConfigNode& list, const RunConfig& config) {
  const std::vector<ConfigNode> elements = list.elements();
  for (std::size_t i = 0; i < config.sensors.size(); ++i) {
    const auto* cwtof = std::get_if<sensors::CwTofParams>(&config.sensors[i].params);
    if (!cwtof || !cwtof->multipath_by_order) continue;
    if (!config.output.depth) {
      elements[i].failKey("multipath_by_order",
                          "needs the ground-truth depth: set output.depth: true");
    }
    if (config.renderer == RendererKind::Reference && config.reference.bounces > 2) {
      elements[i].failKey(
          "multipath_by_order",
          "the reference renderer does not split its indirect light by bounce (render.reference."
          "bounces: " +
              std::to_string(config.reference.bounces) +
              "); use renderer: ir with render.indirect.bounces, or reference.bounces <= 2");
    }
  }
}

// A SPAD gate must open inside the TDC's window (its bins on the render's
// axis), or the detector never counts.
void checkSpadGates(const ConfigNode& list, const RunConfig& config) {
  const std::vector<ConfigNode> elements = list.elements();
  for (std::size_t i = 0; i < config.sensors.size(); ++i) {
    const auto* spad = std::get_if<sensors::SpadParams>(&config.sensors[i].params);
    if (!spad) continue;
    const TimeAxis tdc = sensors::resolveBins(spad->bins, config.render.time);
    if (spad->tdc_dnl.present() && static_cast<int32_t>(spad->tdc_dnl.values.size()) != tdc.bins) {
      elements[i].failKey("tdc_dnl", "has " + std::to_string(spad->tdc_dnl.values.size()) +
                                         " values but the TDC has " + std::to_string(tdc.bins) +
                                         " bins (one DNL per bin)");
    }
    if (spad->tdc_dnl.present()) checkDnlSum(elements[i], spad->tdc_dnl);
    if (spad->gate_width_s <= 0.0) continue;
    const double g0 = spad->gate_start_s, g1 = g0 + spad->gate_width_s;
    if (!(g1 > tdc.start_s && g0 < tdc.end_s())) {
      elements[i].failKey("gate_start", "the gate [" + shortest(g0 * 1e9) + ", " +
                                            shortest(g1 * 1e9) +
                                            ") ns lies outside the TDC's "
                                            "window [" +
                                            shortest(tdc.start_s * 1e9) + ", " +
                                            shortest(tdc.end_s() * 1e9) + ") ns");
    }
    // A gate sweep's last position too (the positions move linearly).
    const double last =
        spad->gated_frames > 0 ? (spad->gate_positions - 1) * spad->gate_step_s : 0.0;
    if (!(g1 + last > tdc.start_s && g0 + last < tdc.end_s())) {
      elements[i].failKey("gate_step", "the last gate position [" + shortest((g0 + last) * 1e9) +
                                           ", " + shortest((g1 + last) * 1e9) +
                                           ") ns lies outside the TDC's window [" +
                                           shortest(tdc.start_s * 1e9) + ", " +
                                           shortest(tdc.end_s() * 1e9) + ") ns");
    }
  }
}

// "sensors.0.bins" -> "sensors[0].bins", the form ConfigNode paths take.
std::string nodePath(const std::string& keyPath) {
  std::string out;
  std::size_t begin = 0;
  while (begin <= keyPath.size()) {
    const std::size_t dot = keyPath.find('.', begin);
    const std::string part = keyPath.substr(begin, dot == std::string::npos ? dot : dot - begin);
    const bool index = !part.empty() && part.find_first_not_of("0123456789") == std::string::npos;
    out += index ? "[" + part + "]" : (out.empty() ? "" : ".") + part;
    if (dot == std::string::npos) break;
    begin = dot + 1;
  }
  return out;
}

// The RSM makes one VPL per texel of each light view: one view for spots up
// to 60 degrees (half angle), six cube faces otherwise (Vpls.cpp). Bounded so
// that a typo cannot ask for hours of work or more VPLs than a dispatch can
// index.
constexpr long long kMaxVpls = 1LL << 22;

void checkVplCount(const ConfigNode& root, const RunConfig& config) {
  const capture::Light& light = config.light.light;
  const capture::IndirectSettings& s = config.render.indirect;
  // As ir::rsmViews.
  const long long faces =
      light.type == capture::Light::Type::Lambertian                                   ? 5
      : light.type == capture::Light::Type::Spot && light.cone_half_angle_deg <= 60.0f ? 1
                                                                                       : 6;
  const long long side = s.rsm_resolution;
  const long long first = faces * side * side;
  // Every later bounce traces vpls_per_bounce (0: as many as the first) VPLs.
  const long long later = (s.bounces - 1) * (s.vpls_per_bounce > 0 ? s.vpls_per_bounce : first);
  if (s.enabled && first + later > kMaxVpls) {
    const ConfigNode render = root.child("render");
    const ConfigNode indirect = render.child("indirect");
    std::string what = std::to_string(side) + "^2 x " + std::to_string(faces) +
                       " light view(s) = " + std::to_string(first) + " VPLs";
    if (later > 0) what += " + " + std::to_string(later) + " of later bounces";
    indirect.failKey(later > 0 ? "bounces" : "rsm_resolution",
                     what + ", more than the limit of " + std::to_string(kMaxVpls));
  }
}

// Defocus (camera.aperture) is gathered by the CPU IR backend only: the GL
// backend does not take aperture samples (render.backend: auto picks the CPU
// for it; the reference path tracer refuses it when it renders).
void checkDefocusBackend(const ConfigNode& root, const RunConfig& config) {
  if (config.nlos || !config.camera.camera.defocused()) return;
  if (config.renderer != RendererKind::InstantRadiosity || config.backend != IrBackendKind::Gl) {
    return;
  }
  root.child("camera").failKey(
      "aperture",
      "defocus runs on render.backend: cpu (or auto); the gl backend does not gather "
      "aperture samples");
}

// render.indirect.merge_pixel_samples is gathered by the CPU IR backend only.
void checkMergeBackend(const ConfigNode& root, const RunConfig& config) {
  if (config.nlos || !config.render.indirect.merge_pixel_samples ||
      config.render.pixel_samples == 1) {
    return;
  }
  if (config.renderer != RendererKind::InstantRadiosity || config.backend != IrBackendKind::Gl) {
    return;
  }
  root.child("render").child("indirect").failKey(
      "merge_pixel_samples",
      "runs on render.backend: cpu (or auto); the gl backend gathers every pixel sample");
}

// sequence.mp4 is made of the frames' steady.exr: without them there is no
// video, which is said rather than skipped. Its default follows
// output.steady (so the effective config, which writes both, reloads).
void checkSequenceVideo(const ConfigNode& sequence, RunConfig& config) {
  if (config.output.steady) return;
  if (sequence.has("video") && config.sequence->video) {
    sequence.failKey("video",
                     "sequence.mp4 is made of the frames' steady images: it needs "
                     "output.steady: true (or set sequence.video: false)");
  }
  config.sequence->video = false;
}

// What an nlos capture cannot do: the outputs of a camera image.
void checkNlosRun(const ConfigNode& root) {
  if (const auto output = root.optionalChild("output")) {
    for (const char* key :
         {"steady", "depth", "frames", "video", "frame_pngs", "components", "video_tone_map",
          "video_stride", "video_window", "video_fps", "plot_ranges"}) {
      if (output->has(key)) {
        output->failKey(key,
                        "does not apply to an nlos capture (it writes H.npy, its grids and "
                        "capture.hdf5: configs/README.md, `nlos`)");
      }
    }
  }
}

}  // namespace

Override parseOverride(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError("--set expects key.path=value (got '" + text + "')");
  }
  return Override{text.substr(0, eq), text.substr(eq + 1)};
}

RunConfig loadRunConfig(const std::filesystem::path& file, const std::vector<Override>& overrides) {
  return loadRunConfigYaml(loadYamlFile(file.string()), file, overrides);
}

RunConfig loadRunConfigYaml(YAML::Node yaml, const std::filesystem::path& file,
                            const std::vector<Override>& overrides) {
  if (!yaml.IsMap())
    throw InputError(FileLoc{file.string(), 1, 1}, "", "the config must be a mapping");
  for (const Override& o : overrides) applyOverride(yaml, o.keyPath, o.value);
  const ConfigNode root(yaml, file.string());
  for (const Override& o : overrides) {
    root.addOverrideSource(nodePath(o.keyPath), "--set " + o.keyPath + "=" + o.value);
  }

  RunConfig config;
  config.config_file = file;
  const std::string sceneText = root.requireString("scene");
  config.scene_file = file.parent_path() / sceneText;
  // The error_code overload: a name the OS rejects (too long, ...) is bad
  // input, not a std::filesystem_error escaping (found by fuzz_config).
  std::error_code ec;
  if (!std::filesystem::exists(config.scene_file, ec)) {
    root.failKey("scene", "scene file not found: " + config.scene_file.string());
  }
  if (const auto nlos = root.optionalChild("nlos")) {
    config.nlos = parseNlos(*nlos);
    for (const char* key : {"camera", "light"}) {
      if (root.has(key)) {
        root.failKey(key,
                     "an nlos capture looks at the relay wall from nlos.sensor_origin and is "
                     "lit by nlos.laser_*: remove `" +
                         std::string(key) + "`");
      }
    }
    config.light.light.type = capture::Light::Type::Lambertian;
    config.light.light.intensity_W_per_sr = config.nlos->laser_power_W;
  } else {
    parseCamera(root.child("camera"), config.camera);
    parseLight(root.child("light"), config.light);
  }
  if (const auto sequence = root.optionalChild("sequence")) {
    if (config.nlos)
      sequence->fail("a sequence of nlos captures is not supported (remove `nlos` or `sequence`)");
    config.sequence = parseSequence(*sequence);
  }
  if (const auto time = root.optionalChild("time")) {
    parseTime(*time, config.render);
  } else {
    root.failKey("time", "required key is missing (start, bin_width, bins)");
  }
  if (const auto render = root.optionalChild("render")) parseRender(*render, config);
  checkVplCount(root, config);
  checkDefocusBackend(root, config);
  checkMergeBackend(root, config);
  if (const auto output = root.optionalChild("output")) parseOutput(*output, config, config.output);
  if (config.sequence) checkSequenceVideo(root.child("sequence"), config);
  if (config.nlos) checkNlosRun(root);
  if (const auto list = root.optionalChild("sensors")) {
    // parseSensors reports unknown keys inside each sensor itself; the keys it
    // read are shared with `root`, so the check below neither repeats nor
    // misses them.
    config.sensors = parseSensors(*list);
    checkSensorNames(*list, config.sensors);
    // An nlos capture's sensor image: a row per sensor x (and laser point), a
    // column per sensor y (apps/pipeline NlosSensors.h).
    capture::Camera image = config.camera.camera;
    if (config.nlos) {
      const NlosConfig& n = *config.nlos;
      const int32_t lasers = n.scan == NlosScan::Exhaustive ? n.laser_grid[0] * n.laser_grid[1] : 1;
      image.width = n.sensor_grid[1];
      image.height = n.sensor_grid[0] * lasers;
    }
    checkSensorsFitImage(*list, config.sensors, image);
    checkBounceOrders(*list, config);
    checkSpadGates(*list, config);
    checkSensorKernels(*list, config.sensors, config.render.time);
  }
  root.reportUnusedKeys();
  return config;
}

}  // namespace tofsim::config
