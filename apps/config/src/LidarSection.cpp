#include "LidarSection.h"

#include <cmath>
#include <string>
#include <vector>

#include "ShortestNumber.h"
#include "Vec3Key.h"
#include "LidarScanSection.h"

namespace tofsim::config {

const char* beamProfileName(lidar::BeamProfile profile) {
  return profile == lidar::BeamProfile::Tophat ? "tophat" : "gaussian";
}

const char* returnModeName(lidar::ReturnMode mode) {
  switch (mode) {
    case lidar::ReturnMode::First: return "first";
    case lidar::ReturnMode::Strongest: return "strongest";
    case lidar::ReturnMode::Last: return "last";
    case lidar::ReturnMode::Dual: return "dual";
    case lidar::ReturnMode::All: return "all";
  }
  return "strongest";
}

const char* scanPatternName(lidar::ScanPattern scan) {
  switch (scan) {
    case lidar::ScanPattern::Spinning: return "spinning";
    case lidar::ScanPattern::Raster: return "raster";
    case lidar::ScanPattern::Zones: return "zones";
  }
  return "spinning";
}

namespace {

constexpr int32_t kMaxChannels = 1024;
constexpr int32_t kMaxAzimuths = 1 << 20;

glm::vec3 finiteVec3(const ConfigNode& node, const char* key, const glm::vec3& fallback) {
  const glm::vec3 v = vec3Of(node, key, fallback);
  if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) node.failKey(key, "must be finite [x, y, z] in metres");
  return v;
}

void parseOrientation(const ConfigNode& lidarNode, LidarConfig& out) {
  if (!lidarNode.has("orientation")) {
    lidarNode.failKey("orientation", "required key is missing ({look_at: [x, y, z], up: [x, y, z]})");
  }
  const ConfigNode o = lidarNode.child("orientation");
  if (!o.isMap()) o.fail("expected {look_at: [x, y, z], up: [x, y, z]}");
  if (!o.has("look_at")) o.failKey("look_at", "required key is missing ([x, y, z] in metres)");
  out.look_at_world = finiteVec3(o, "look_at", {});
  const glm::vec3 up = finiteVec3(o, "up", {0.0f, 0.0f, 1.0f});
  out.up_written = up;
  if (!(glm::length(up) > 0.0f)) o.failKey("up", "must not be zero (the spin axis)");
  lidar::LidarSpec& s = out.spec;
  s.up_world = glm::normalize(up);
  const glm::vec3 d = out.look_at_world - s.position_world;
  const glm::vec3 forward = d - glm::dot(d, s.up_world) * s.up_world;
  if (!(glm::length(forward) > 1e-6f * std::max(1.0f, glm::length(d)))) {
    o.failKey("look_at", "must not lie on the spin axis (`up` through `position`): azimuth 0 looks at it");
  }
  s.forward_world = glm::normalize(forward);
  // A grid scan looks at look_at itself (up only sets its roll: ScanGrid.h).
  if (s.gridScan()) s.forward_world = glm::normalize(d);
}

void parseChannels(const ConfigNode& lidarNode, LidarConfig& out) {
  if (!lidarNode.has("channels")) {
    if (!out.spec.elevations_deg.empty()) return;  // a preset's
    lidarNode.failKey("channels", "required key is missing ({count, min, max} in degrees, or a list of elevations)");
  }
  const ConfigNode c = lidarNode.child("channels");
  std::vector<double>& el = out.spec.elevations_deg;
  el.clear();  // the config's channels replace a preset's
  out.channel_count = 0;
  if (c.isSequence()) {
    for (const ConfigNode& e : c.elements()) el.push_back(e.asDouble());
    if (el.empty()) c.fail("no channels: list at least one elevation (degrees)");
  } else {
    if (!c.isMap()) c.fail("expected {count, min, max} or a list of elevations (degrees)");
    const long long count = c.getInt("count", 0);
    if (count < 1 || count > kMaxChannels) {
      c.failKey("count", "no channels: count must be in [1, " + std::to_string(kMaxChannels) + "]");
    }
    out.channel_count = static_cast<int32_t>(count);
    out.channel_min_deg = c.getAngle_deg("min", 0.0);
    out.channel_max_deg = c.getAngle_deg("max", out.channel_min_deg);
    if (out.channel_max_deg < out.channel_min_deg) c.failKey("max", "must be >= min");
    if (count > 1 && !(out.channel_max_deg > out.channel_min_deg)) {
      c.failKey("max", "must be > min with more than one channel");
    }
    for (long long i = 0; i < count; ++i) {
      el.push_back(count == 1 ? out.channel_min_deg
                              : out.channel_min_deg + (out.channel_max_deg - out.channel_min_deg) *
                                                          double(i) / double(count - 1));
    }
  }
  if (static_cast<int32_t>(el.size()) > kMaxChannels) {
    c.fail("at most " + std::to_string(kMaxChannels) + " channels");
  }
  for (double e : el) {
    if (!(e >= -90.0 && e <= 90.0)) c.fail("elevations must be in [-90, 90] degrees");
  }
}

void parseAzimuth(const ConfigNode& lidarNode, lidar::LidarSpec& s) {
  if (!lidarNode.has("azimuth")) return;
  const ConfigNode a = lidarNode.child("azimuth");
  if (!a.isMap()) a.fail("expected {start, end, step} in degrees");
  s.azimuth_start_deg = a.getAngle_deg("start", s.azimuth_start_deg);
  s.azimuth_end_deg = a.getAngle_deg("end", s.azimuth_end_deg);
  s.azimuth_step_deg = a.getAngle_deg("step", s.azimuth_step_deg);
  if (!(s.azimuth_step_deg > 0.0)) a.failKey("step", "must be > 0 degrees");
  if (!(s.azimuth_end_deg > s.azimuth_start_deg)) a.failKey("end", "must be > start");
  if (s.azimuth_end_deg - s.azimuth_start_deg > 360.0 + 1e-9) {
    a.failKey("end", "end - start must be at most 360 degrees (one turn)");
  }
  if (s.azimuths() > kMaxAzimuths) {
    a.failKey("step", "gives more than " + std::to_string(kMaxAzimuths) + " azimuths");
  }
}

// A small angle that needs its unit (beam_divergence, multipath.receiver_fov).
double angleWithUnit_rad(const ConfigNode& n, const char* key) {
  const std::string text = n.child(key).asString();
  // A bare number could be degrees or milliradians: a unit is needed.
  if (text.find_first_not_of("0123456789.+-eE ") == std::string::npos) {
    n.failKey(key, "needs a unit: '3 mrad', '0.2 deg' (got '" + text + "')");
  }
  // Radians and milliradians read as they are written (the effective
  // config's "rad" gives back the same double); degrees through
  // parseAngle_deg.
  const std::size_t unit = text.find_last_not_of(" ");
  const bool mrad = text.size() > 4 && text.compare(unit - 3, 4, "mrad") == 0;
  const bool rad = !mrad && text.size() > 3 && text.compare(unit - 2, 3, "rad") == 0;
  if (mrad || rad) {
    try {
      return std::stod(text.substr(0, unit - (mrad ? 3 : 2))) / (mrad ? 1000.0 : 1.0);
    } catch (const std::exception&) {
      n.failKey(key, "expected an angle such as '3 mrad' (got '" + text + "')");
    }
  }
  return glm::radians(n.getAngle_deg(key, 0.0));
}

void parseDivergence(const ConfigNode& n, lidar::LidarSpec& s) {
  if (n.has("beam_divergence")) s.divergence_rad = angleWithUnit_rad(n, "beam_divergence");
  if (!(s.divergence_rad > 0.0) || s.divergence_rad >= M_PI / 2) {
    n.failKey("beam_divergence", "must be > 0 and below 90 degrees (the full angle)");
  }
  const std::string profile = n.getString("beam_profile", beamProfileName(s.profile));
  if (profile == "gaussian") {
    s.profile = lidar::BeamProfile::Gaussian;
  } else if (profile == "tophat") {
    s.profile = lidar::BeamProfile::Tophat;
  } else {
    n.failKey("beam_profile", "must be gaussian or tophat (got '" + profile + "')");
  }
  const long long rays = n.getInt("beam_rays", s.beam_rays);
  if (rays < 1 || rays > 4096) n.failKey("beam_rays", "must be in [1, 4096]");
  s.beam_rays = static_cast<int32_t>(rays);
}

void parseReturns(const ConfigNode& lidarNode, lidar::ReturnSettings& r) {
  if (!lidarNode.has("returns")) return;
  const ConfigNode n = lidarNode.child("returns");
  if (!n.isMap()) n.fail("expected {mode, max, threshold, separation}");
  const std::string mode = n.getString("mode", returnModeName(r.mode));
  bool known = false;
  for (auto m : {lidar::ReturnMode::First, lidar::ReturnMode::Strongest, lidar::ReturnMode::Last,
                 lidar::ReturnMode::Dual, lidar::ReturnMode::All}) {
    if (mode == returnModeName(m)) {
      r.mode = m;
      known = true;
    }
  }
  if (!known) n.failKey("mode", "must be first, strongest, last, dual or all (got '" + mode + "')");
  const long long max = n.getInt("max", r.max);
  if (max < 1 || max > 255) n.failKey("max", "must be in [1, 255]");
  r.max = static_cast<int32_t>(max);
  r.threshold = n.getDouble("threshold", r.threshold);
  if (!(r.threshold >= 0.0 && std::isfinite(r.threshold))) n.failKey("threshold", "must be >= 0");
  r.separation_m = n.getLength_m("separation", r.separation_m);
  if (!(r.separation_m >= 0.0 && std::isfinite(r.separation_m))) {
    n.failKey("separation", "must be a length >= 0");
  }
}

void parsePlotBeams(const ConfigNode& lidarNode, LidarConfig& out) {
  if (!lidarNode.has("plot_beams")) return;
  const ConfigNode list = lidarNode.child("plot_beams");
  const lidar::LidarSpec& s = out.spec;
  for (const ConfigNode& beam : list.elements()) {
    std::vector<double> v;
    if (beam.isSequence()) {
      for (const ConfigNode& e : beam.elements()) v.push_back(e.asDouble());
    }
    if (v.size() != 2) {
      beam.fail(s.gridScan() ? "expected [row, column]" : "expected [ring, azimuth in degrees]");
    }
    const double a = s.gridScan() ? v[1] : std::round((v[1] - s.azimuth_start_deg) / s.azimuth_step_deg);
    if (!(v[0] >= 0 && v[0] < s.channels() && v[0] == std::floor(v[0]))) {
      beam.fail("the ring must be an integer in [0, " + std::to_string(s.channels()) + ")");
    }
    if (!(a >= 0 && a < s.azimuths() && a == std::floor(a))) {
      beam.fail(s.gridScan() ? "the column must be an integer in [0, " +
                                   std::to_string(s.azimuths()) + ")"
                             : std::string("the azimuth is outside lidar.azimuth"));
    }
    out.plot_beams.push_back({static_cast<int32_t>(v[0]), static_cast<int32_t>(a)});
  }
}

// lidar.multipath: a beam's light that bounces before it returns
// (core/lidar MultipathWaveforms.h); off unless asked for.
void parseMultipath(const ConfigNode& lidarNode, LidarConfig& out) {
  if (!lidarNode.has("multipath")) return;
  if (out.spec.scan == lidar::ScanPattern::Zones) {
    lidarNode.failKey("multipath", "a zone scan's flood emitter has no spot: multipath is built "
                                   "for spinning and raster scans");
  }
  const ConfigNode n = lidarNode.child("multipath");
  if (!n.isMap())
    n.fail("expected {bounces, spot_rays, receiver_rays, receiver_fov, vpls_per_bounce}");
  lidar::MultipathSettings& m = out.multipath;
  const auto count = [&](const char* key, long long fallback, long long lo, long long hi) {
    const long long v = n.getInt(key, fallback);
    if (v < lo || v > hi) {
      n.failKey(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
    return static_cast<int32_t>(v);
  };
  m.bounces = count("bounces", m.bounces, 0, 8);
  m.spot_rays = count("spot_rays", m.spot_rays, 1, 1024);
  m.receiver_rays = count("receiver_rays", m.receiver_rays, 1, 4096);
  m.vpls_per_bounce = count("vpls_per_bounce", m.vpls_per_bounce, 1, 4096);
  const double divergence = out.spec.divergence_rad;
  if (n.has("receiver_fov")) {
    m.receiver_fov_rad = angleWithUnit_rad(n, "receiver_fov");
    if (!(m.receiver_fov_rad >= divergence) || m.receiver_fov_rad >= M_PI) {
      n.failKey("receiver_fov", "must be at least the beam_divergence (" + shortest(divergence) +
                                    " rad) and below 180 degrees");
    }
  }
}

// `backscatter: {overlap, phase_at_pi}`: the medium's light along the beams
// (core/lidar BeamBackscatter.h); apd43's block.
void parseBackscatter(const ConfigNode& lidarNode, lidar::BackscatterSettings& b) {
  if (!lidarNode.has("backscatter")) return;
  const ConfigNode n = lidarNode.child("backscatter");
  if (!n.isMap()) n.fail("expected {overlap, phase_at_pi}");
  b.overlap_m = n.getLength_m("overlap", b.overlap_m);
  if (!(b.overlap_m > 0.0 && std::isfinite(b.overlap_m))) {
    n.failKey("overlap", "must be a length > 0 (the backscatter's 1 / r^2 diverges at the lidar)");
  }
  b.phase_at_pi_per_sr = n.getDouble("phase_at_pi", b.phase_at_pi_per_sr);
  if (!(b.phase_at_pi_per_sr >= 0.0 && std::isfinite(b.phase_at_pi_per_sr))) {
    n.failKey("phase_at_pi", "must be >= 0 (1/sr; 0: the medium's phase function)");
  }
}

}  // namespace

void parseLidarView(const ConfigNode& root, RunConfig& config) {
  for (const char* key : {"camera", "nlos", "rays", "light"}) {
    if (root.has(key)) {
      root.failKey(key, "a lidar capture has its own beams from `lidar.position` (no camera, "
                        "light, rays or nlos scan): remove `" + std::string(key) + "` or `lidar`");
    }
  }
  const ConfigNode n = root.child("lidar");
  if (!n.isMap()) n.fail("expected a mapping (position, orientation, channels, azimuth, ...)");
  auto out = std::make_shared<LidarConfig>();
  out->at = n.location();
  applyLidarPreset(n, *out, config.render.time);
  parseLidarScan(n, out->spec);
  if (!n.has("position")) n.failKey("position", "required key is missing ([x, y, z] in metres)");
  out->spec.position_world = finiteVec3(n, "position", {});
  parseOrientation(n, *out);
  if (!out->spec.gridScan()) {
    parseChannels(n, *out);
    parseAzimuth(n, out->spec);
  }
  if (out->spec.scan != lidar::ScanPattern::Zones) parseDivergence(n, out->spec);
  out->spec.power_W = n.getDouble("power", out->spec.power_W);
  if (!(out->spec.power_W > 0.0 && std::isfinite(out->spec.power_W))) {
    n.failKey("power", "must be > 0 W");
  }
  out->rotation_rate_Hz = n.getFrequency_Hz("rotation_rate", out->rotation_rate_Hz);
  if (!(out->rotation_rate_Hz > 0.0 && std::isfinite(out->rotation_rate_Hz))) {
    n.failKey("rotation_rate", "must be > 0 Hz");
  }
  out->frame_rate_Hz = n.getFrequency_Hz("frame_rate", out->frame_rate_Hz);
  if (!(out->frame_rate_Hz > 0.0 && std::isfinite(out->frame_rate_Hz))) {
    n.failKey("frame_rate", "must be > 0 Hz");
  }
  parseReturns(n, out->spec.returns);
  parseBackscatter(n, out->spec.backscatter);
  parsePlotBeams(n, *out);
  parseMultipath(n, *out);
  config.camera.camera.width = out->spec.azimuths();
  config.camera.camera.height = out->spec.channels();
  config.lidar = std::move(out);
}

namespace {

// A lidar's `sequence` (rolling scans, core/lidar RollingScan.h): frame k
// is the scan from t_k, each beam at its own firing time (a spinning
// lidar's columns, a raster's cells; the multipath and the medium's
// backscatter too); a camera's video and exposure samples do not apply.
void checkLidarSequence(const ConfigNode& root, const LidarConfig& lidarConfig) {
  const auto seq = root.optionalChild("sequence");
  if (!seq) return;
  if (lidarConfig.spec.scan == lidar::ScanPattern::Zones) {
    root.failKey("sequence", "a zone scan's flood lights every zone in one exposure: it has no "
                             "firing order to roll (a rolling scan is a spinning lidar's or a "
                             "raster's); remove `sequence` or use `scan: raster`");
  }
  for (const char* key : {"video", "exposure_samples"}) {
    if (seq->has(key)) {
      seq->failKey(key, "does not apply to a lidar's sequence (frame k is the lidar's turn "
                        "from its time, each azimuth column at its own firing time: "
                        "configs/README.md, `lidar`)");
    }
  }
}

}  // namespace

void checkLidarRun(const ConfigNode& root, const LidarConfig& lidarConfig) {
  checkLidarSequence(root, lidarConfig);
  if (const auto output = root.optionalChild("output")) {
    for (const char* key : {"steady", "depth", "frames", "video", "frame_pngs", "components",
                            "video_tone_map", "video_stride", "video_window", "video_fps",
                            "format"}) {
      if (output->has(key)) {
        output->failKey(key, "does not apply to a lidar capture (it writes waveforms.npy, its "
                             "range and intensity images and point clouds: configs/README.md, "
                             "`lidar`)");
      }
    }
  }
}

YAML::Node lidarNode(const LidarConfig& c) {
  const lidar::LidarSpec& s = c.spec;
  const auto vec = [](const glm::vec3& v) {
    YAML::Node n(YAML::NodeType::Sequence);
    for (int i = 0; i < 3; ++i) n.push_back(shortest(v[i]));
    n.SetStyle(YAML::EmitterStyle::Flow);
    return n;
  };
  YAML::Node n;
  if (!c.preset.empty()) n["preset"] = c.preset;
  n["scan"] = scanPatternName(s.scan);
  n["position"] = vec(s.position_world);
  n["orientation"]["look_at"] = vec(c.look_at_world);
  n["orientation"]["up"] = vec(c.up_written);
  if (s.gridScan()) {
    n["grid"]["rows"] = s.grid.rows;
    n["grid"]["columns"] = s.grid.columns;
    n["field_of_view"]["horizontal"] = shortest(s.grid.fov_horizontal_deg);
    n["field_of_view"]["vertical"] = shortest(s.grid.fov_vertical_deg);
    if (s.scan == lidar::ScanPattern::Zones) n["zone_rays"] = s.grid.zone_rays;
  } else if (c.channel_count > 0) {
    n["channels"]["count"] = c.channel_count;
    n["channels"]["min"] = shortest(c.channel_min_deg);
    n["channels"]["max"] = shortest(c.channel_max_deg);
  } else {
    YAML::Node list(YAML::NodeType::Sequence);
    for (double e : s.elevations_deg) list.push_back(shortest(e));
    list.SetStyle(YAML::EmitterStyle::Flow);
    n["channels"] = list;
  }
  if (!s.gridScan()) {
    n["azimuth"]["start"] = shortest(s.azimuth_start_deg);
    n["azimuth"]["end"] = shortest(s.azimuth_end_deg);
    n["azimuth"]["step"] = shortest(s.azimuth_step_deg);
  }
  if (s.scan != lidar::ScanPattern::Zones) {
    n["beam_divergence"] = shortest(s.divergence_rad) + " rad";
    n["beam_profile"] = beamProfileName(s.profile);
    n["beam_rays"] = s.beam_rays;
  }
  n["power"] = shortest(s.power_W);
  if (!s.gridScan()) n["rotation_rate"] = shortest(c.rotation_rate_Hz) + " Hz";
  if (s.scan == lidar::ScanPattern::Raster) n["frame_rate"] = shortest(c.frame_rate_Hz) + " Hz";
  n["returns"]["mode"] = returnModeName(s.returns.mode);
  n["returns"]["max"] = s.returns.max;
  n["returns"]["threshold"] = shortest(s.returns.threshold);
  n["returns"]["separation"] = shortest(s.returns.separation_m) + " m";
  YAML::Node beams(YAML::NodeType::Sequence);
  for (const auto& [ring, a] : c.plot_beams) {
    YAML::Node beam(YAML::NodeType::Sequence);
    beam.push_back(ring);
    if (s.gridScan()) {
      beam.push_back(a);
    } else {
      beam.push_back(shortest(s.azimuthOf_deg(a)));
    }
    beam.SetStyle(YAML::EmitterStyle::Flow);
    beams.push_back(beam);
  }
  beams.SetStyle(YAML::EmitterStyle::Flow);
  n["plot_beams"] = beams;
  if (c.multipath.enabled()) {  // only when asked for: the effective configs of before stay
    const lidar::MultipathSettings& m = c.multipath;
    n["multipath"]["bounces"] = m.bounces;
    n["multipath"]["spot_rays"] = m.spot_rays;
    n["multipath"]["receiver_rays"] = m.receiver_rays;
    n["multipath"]["receiver_fov"] =
        shortest(m.receiver_fov_rad > 0.0 ? m.receiver_fov_rad : s.divergence_rad) + " rad";
    n["multipath"]["vpls_per_bounce"] = m.vpls_per_bounce;
  }
  n["backscatter"]["overlap"] = shortest(s.backscatter.overlap_m) + " m";
  n["backscatter"]["phase_at_pi"] = shortest(s.backscatter.phase_at_pi_per_sr);
  return n;
}

}  // namespace tofsim::config
