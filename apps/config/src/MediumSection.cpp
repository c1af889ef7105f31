#include "MediumSection.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "ShortestNumber.h"
#include "tofsim/config/Units.h"
#include "tofsim/physics/MediumPhysics.h"

namespace tofsim::config {

namespace {

struct PhaseName {
  const char* name;
  int32_t model;
};
constexpr PhaseName kPhases[] = {{"isotropic", physics::PHASE_ISOTROPIC},
                                 {"henyey_greenstein", physics::PHASE_HENYEY_GREENSTEIN},
                                 {"rayleigh", physics::PHASE_RAYLEIGH}};

// One channel's value of sigma_a or sigma_s (a number in 1/m, or with a unit:
// "0.04 /m", "4 1/km") or of the albedo (in [0, 1]), as the float the
// renderers take.
float channelValue(const ConfigNode& e, bool attenuation) {
  double v = 0.0;
  if (attenuation) {
    try {
      v = parseAttenuation_per_m(e.asString());
    } catch (const std::invalid_argument& error) {
      e.fail(error.what());
    }
  } else {
    v = e.asDouble();
  }
  const std::string got = " (got " + e.asString() + ")";
  if (!(v >= 0.0)) e.fail("must be >= 0" + got);
  if (!attenuation && v > 1.0) e.fail("must be in [0, 1]" + got);
  if (!std::isfinite(static_cast<float>(v))) e.fail("is too large for a float" + got);
  return static_cast<float>(v);
}

// `key`: one number for every channel or [R, G, B].
glm::vec3 perChannel(const ConfigNode& n, const char* key, bool attenuation) {
  const ConfigNode c = n.child(key);
  if (c.isScalar()) return glm::vec3(channelValue(c, attenuation));
  if (!c.isSequence() || c.yaml().size() != 3) {
    c.fail(std::string("expected one number (every channel) or a list of 3, [R, G, B]") +
           (attenuation ? ", in 1/m" : "") +
           (c.isSequence() ? " (got " + std::to_string(c.yaml().size()) + " values)" : ""));
  }
  const std::vector<ConfigNode> e = c.elements();
  return {channelValue(e[0], attenuation), channelValue(e[1], attenuation),
          channelValue(e[2], attenuation)};
}

// `phase`: {model: ..., g: ...}, or the model's name alone.
void parsePhase(const ConfigNode& n, capture::Medium& m) {
  const ConfigNode p = n.child("phase");
  if (!p.isScalar() && !p.isMap()) {
    p.fail("expected {model: isotropic, henyey_greenstein or rayleigh, g: ...} or a model's name");
  }
  const std::string model = p.isMap() ? p.requireString("model") : p.asString();
  const PhaseName* found = nullptr;
  for (const PhaseName& phase : kPhases) found = model == phase.name ? &phase : found;
  if (!found) {
    const std::string message =
        "must be isotropic, henyey_greenstein or rayleigh (got '" + model + "')";
    if (p.isMap()) p.failKey("model", message);
    p.fail(message);
  }
  m.phase = found->model;
  m.g = 0.0f;
  if (m.phase != physics::PHASE_HENYEY_GREENSTEIN) {
    if (p.isMap() && p.has("g")) {
      p.failKey("g", "is the henyey_greenstein model's asymmetry (this is model: " + model + ")");
    }
    return;
  }
  if (!p.isMap())
    p.fail("henyey_greenstein needs its asymmetry: {model: henyey_greenstein, g: 0.6}");
  const double g = p.requireDouble("g");
  if (!(g > -1.0 && g < 1.0)) p.failKey("g", "must be in (-1, 1) (got " + shortest(g) + ")");
  m.g = static_cast<float>(g);
}

// `visibility` (fog): sigma_t = 3.912 / V, split by the albedo; fog's phase
// function unless `phase` says otherwise.
void parseVisibility(const ConfigNode& n, capture::Medium& m, MediumConfig& form) {
  for (const char* key : {"sigma_a", "sigma_s"}) {
    if (n.has(key)) {
      n.failKey(key,
                "`visibility` sets the fog's sigma_a and sigma_s (Koschmieder): give `visibility` "
                "or sigma_a and sigma_s, not both");
    }
  }
  const double v = n.getLength_m("visibility", 0.0);
  const double sigmaT = kKoschmieder / v;
  if (!(v > 0.0) || !std::isfinite(static_cast<float>(sigmaT))) {
    n.failKey("visibility", "must be a length > 0 (got " + n.child("visibility").asString() + ")");
  }
  form.visibility_m = v;
  form.albedo = n.has("albedo") ? perChannel(n, "albedo", false) : glm::vec3(kFogAlbedo);
  for (int c = 0; c < 3; ++c) {
    m.sigma_s_per_m[c] = static_cast<float>(form.albedo[c] * sigmaT);
    m.sigma_a_per_m[c] = static_cast<float>((1.0 - form.albedo[c]) * sigmaT);
  }
  m.phase = physics::PHASE_HENYEY_GREENSTEIN;
  m.g = kFogG;
}

// The medium's index of refraction is the time axis's: given in both places,
// they must agree.
void parseIndex(const ConfigNode& root, const ConfigNode& n, TimeAxis& time) {
  if (!n.has("index_of_refraction")) return;
  const double eta = n.getDouble("index_of_refraction", 1.0);
  if (!(eta >= 1.0)) {
    n.failKey("index_of_refraction", "must be >= 1 (got " + shortest(eta) + ")");
  }
  const auto axis = root.optionalChild("time");
  if (axis && axis->has("index_of_refraction") && time.index_of_refraction != eta) {
    n.failKey("index_of_refraction",
              "is " + shortest(eta) + " but time.index_of_refraction is " +
                  shortest(time.index_of_refraction) + " (" +
                  axis->locationOf("index_of_refraction").toString() +
                  "): the medium's index sets the time axis's; give it once");
  }
  time.index_of_refraction = eta;
}

// What the renderers do not build a medium into yet: a located error rather
// than a render that silently ignores it, at the key that makes the medium
// (a --set of it names the --set).
void refuseUnbuiltCaptures(const ConfigNode& n, const capture::Medium& m, const RunConfig& config) {
  const char* key = n.has("visibility")                                            ? "visibility"
                    : glm::any(glm::greaterThan(m.sigma_s_per_m, glm::vec3(0.0f))) ? "sigma_s"
                                                                                   : "sigma_a";
  if (config.nlos) {
    n.failKey(key,
              "a medium in an nlos capture is not built yet (the relay-wall scan renders in "
              "vacuum): remove `medium` or `nlos`");
  }
  if (config.rays) {
    n.failKey(key,
              "a medium with a ray-list capture (`rays`) is not built yet (its pixels' rays are "
              "not attenuated nor scattered along): use `camera`, or remove `medium`");
  }
}

YAML::Node channelsNode(const glm::vec3& v) {
  if (v.x == v.y && v.y == v.z) return YAML::Node(shortest(v.x));
  YAML::Node n(YAML::NodeType::Sequence);
  for (int c = 0; c < 3; ++c) n.push_back(shortest(v[c]));
  n.SetStyle(YAML::EmitterStyle::Flow);
  return n;
}

}  // namespace

const char* phaseModelName(int32_t phase) {
  for (const PhaseName& p : kPhases) {
    if (p.model == phase) return p.name;
  }
  return "unknown";
}

namespace {

// sigma_a, sigma_s (or visibility and albedo) and the phase function of a
// `medium:` or a `media:` entry.
capture::Medium parseCoefficients(const ConfigNode& n, MediumConfig& form) {
  capture::Medium m;
  if (n.has("visibility")) {
    parseVisibility(n, m, form);
  } else {
    if (n.has("albedo")) {
      n.failKey("albedo",
                "goes with `visibility` (fog); with sigma_a and sigma_s the albedo is "
                "sigma_s / (sigma_a + sigma_s)");
    }
    if (n.has("sigma_a")) m.sigma_a_per_m = perChannel(n, "sigma_a", true);
    if (n.has("sigma_s")) m.sigma_s_per_m = perChannel(n, "sigma_s", true);
  }
  if (n.has("phase")) parsePhase(n, m);
  return m;
}

// What a region's medium is not built into: a located error at the entry.
void refuseUnbuiltRegionCaptures(const ConfigNode& e, const RunConfig& config) {
  if (config.nlos || config.rays || config.lidar || config.sequence) {
    e.fail(std::string("per-region media in ") +
           (config.nlos       ? "an nlos capture"
            : config.rays     ? "a ray-list capture"
            : config.lidar    ? "a lidar capture"
                              : "a capture sequence") +
           " are not built yet: use one `camera` capture, or remove `media`");
  }
}

// What the GL backend does not build into a region's medium: scattering
// (its single scattering and medium VPLs are the CPU backend's, if any). An
// absorbing region (its attenuation and its index's delay) is built on both.
void refuseUnbuiltRegionOnGl(const ConfigNode& e, const capture::Medium& m,
                             const RunConfig& config) {
  if (config.renderer != RendererKind::InstantRadiosity || config.backend == IrBackendKind::Cpu) {
    return;
  }
  if (m.scatters()) {
    e.failKey(e.has("visibility") ? "visibility" : "sigma_s",
              "a scattering region (sigma_s > 0) is not built on the GL backend (render.backend: " +
                  std::string(config.backend == IrBackendKind::Gl ? "gl" : "auto, which may pick gl") +
                  "): set `render.backend: cpu` (or `render.renderer: reference`), or sigma_s: 0");
  }
}

// What instant radiosity does not build into a region's medium yet.
void refuseUnbuiltRegionLight(const ConfigNode& e, const capture::Medium& m,
                              const RunConfig& config) {
  if (config.renderer != RendererKind::InstantRadiosity || !m.scatters()) return;
  const char* key = e.has("visibility") ? "visibility" : "sigma_s";
  if (config.backend != IrBackendKind::Cpu) {
    e.failKey(key,
              "a scattering region (sigma_s > 0) is built on render.backend: cpu and in the "
              "reference only: set `render.backend: cpu` (or `render.renderer: reference`)");
  }
  if (config.render.time.camera_unwarp) {
    e.failKey(key,
              "a scattering region (sigma_s > 0) with time.camera_unwarp is not built in instant "
              "radiosity (its light is binned along the camera ray by a path that grows with "
              "the ray only when the camera leg is timed): set time.camera_unwarp: false, or "
              "`render.renderer: reference`");
  }
}

// One `media:` entry: {region, sigma_a, sigma_s, phase, index_of_refraction}.
void parseRegionMedium(const ConfigNode& e, RunConfig& config) {
  if (!e.isMap()) {
    e.fail("expected a mapping {region, sigma_a, sigma_s, phase, index_of_refraction}");
  }
  capture::RegionMedium r;
  r.region = e.requireString("region");
  for (const capture::RegionMedium& earlier : config.render.media) {
    if (earlier.region == r.region) {
      e.failKey("region", "names '" + r.region + "' twice: one medium per region");
    }
  }
  MediumConfig form;
  r.medium = parseCoefficients(e, form);
  r.index_of_refraction = e.getDouble("index_of_refraction", 1.0);
  if (!(r.index_of_refraction >= 1.0) || !std::isfinite(r.index_of_refraction)) {
    e.failKey("index_of_refraction",
              "must be >= 1 (got " + e.child("index_of_refraction").asString() + ")");
  }
  refuseUnbuiltRegionCaptures(e, config);
  refuseUnbuiltRegionOnGl(e, r.medium, config);
  refuseUnbuiltRegionLight(e, r.medium, config);
  config.render.media.push_back(r);
  config.media.push_back({e.location(), e.locationOf("region")});
}

// `media:`, a list of region media; not with `medium:`.
void parseMedia(const ConfigNode& root, RunConfig& config) {
  const ConfigNode list = root.child("media");
  if (root.has("medium")) {
    root.failKey("media",
                 "a medium filling the scene (`medium`) and per-region media together are not "
                 "built yet: give one of them");
  }
  if (!list.isSequence() || list.yaml().size() == 0) {
    list.fail("expected a list of {region, sigma_a, sigma_s, phase, index_of_refraction}");
  }
  for (const ConfigNode& e : list.elements()) parseRegionMedium(e, config);
}

}  // namespace

void parseMedium(const ConfigNode& root, RunConfig& config) {
  if (root.has("media")) parseMedia(root, config);
  const auto n = root.optionalChild("medium");
  if (!n) return;
  if (!n->isMap()) {
    n->fail(
        "expected a mapping {sigma_a, sigma_s, phase, index_of_refraction} or {visibility, ...}");
  }
  MediumConfig form;
  form.at = n->location();
  const capture::Medium m = parseCoefficients(*n, form);
  parseIndex(root, *n, config.render.time);
  if (m.present()) refuseUnbuiltCaptures(*n, m, config);
  config.render.medium = m;
  config.medium = form;
}

YAML::Node mediumNode(const RunConfig& config) {
  const MediumConfig& form = *config.medium;
  const capture::Medium& m = config.render.medium;
  YAML::Node n;
  if (form.visibility_m > 0.0) {
    n["visibility"] = shortest(form.visibility_m) + " m";
    n["albedo"] = channelsNode(form.albedo);
  } else {
    n["sigma_a"] = channelsNode(m.sigma_a_per_m);
    n["sigma_s"] = channelsNode(m.sigma_s_per_m);
  }
  YAML::Node phase;
  phase["model"] = phaseModelName(m.phase);
  if (m.phase == physics::PHASE_HENYEY_GREENSTEIN) phase["g"] = shortest(m.g);
  phase.SetStyle(YAML::EmitterStyle::Flow);
  n["phase"] = phase;
  n["index_of_refraction"] = shortest(config.render.time.index_of_refraction);
  return n;
}

YAML::Node mediaNode(const RunConfig& config) {
  YAML::Node list(YAML::NodeType::Sequence);
  for (const capture::RegionMedium& r : config.render.media) {
    YAML::Node n;
    n["region"] = r.region;
    n["sigma_a"] = channelsNode(r.medium.sigma_a_per_m);
    n["sigma_s"] = channelsNode(r.medium.sigma_s_per_m);
    YAML::Node phase;
    phase["model"] = phaseModelName(r.medium.phase);
    if (r.medium.phase == physics::PHASE_HENYEY_GREENSTEIN) phase["g"] = shortest(r.medium.g);
    phase.SetStyle(YAML::EmitterStyle::Flow);
    n["phase"] = phase;
    n["index_of_refraction"] = shortest(r.index_of_refraction);
    list.push_back(n);
  }
  return list;
}

}  // namespace tofsim::config
