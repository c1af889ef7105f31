#include "MaterialSection.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "ConfigPath.h"
#include "QuantityText.h"
#include "ResponseTableFile.h"
#include "ShortestNumber.h"

namespace tofsim::config {

namespace {

using physics::ResponseModel;

constexpr const char* kChannel[] = {"R", "G", "B"};

// The keys each model reads; a key of another model is refused by name (it
// would otherwise be an "unknown key" that does not say why).
struct ModelKeys {
  const char* model;
  std::array<const char*, 2> keys;
};
constexpr std::array<ModelKeys, 3> kModels{{{"exponential", {"lifetime", nullptr}},
                                            {"gaussian", {"mean", "sigma"}},
                                            {"table", {"file", "delay_unit"}}}};

double duration(const ConfigNode& n, const char* key, bool positive) {
  const double t = n.child(key).asDuration_s();
  if (positive ? !(t > 0.0) : !(t >= 0.0)) {
    n.failKey(key, std::string("must be ") + (positive ? "> 0" : ">= 0") + " (got " +
                       readableDuration(t) + ")");
  }
  return t;
}

void refuseOtherModelsKeys(const ConfigNode& n, const std::string& model) {
  for (const ModelKeys& m : kModels) {
    if (model == m.model) continue;
    for (const char* key : m.keys) {
      if (key && n.has(key)) {
        n.failKey(key,
                  std::string("is a key of model: ") + m.model + " (this is model: " + model + ")");
      }
    }
  }
}

// Rows: the re-emitted channel; columns: the absorbed one (out = M in). glm
// is column-major: m[j][i] is row i, column j.
glm::dmat3 parseReemission(const ConfigNode& n) {
  const char* form =
      "must be a 3x3 matrix [[R<-R, R<-G, R<-B], [G<-R, G<-G, G<-B], [B<-R, B<-G, B<-B]] "
      "(rows: the re-emitted channel, columns: the absorbed one)";
  if (!n.isSequence() || n.yaml().size() != 3) n.fail(form);
  glm::dmat3 m(0.0);
  const std::vector<ConfigNode> rows = n.elements();
  for (int i = 0; i < 3; ++i) {
    if (!rows[i].isSequence() || rows[i].yaml().size() != 3) rows[i].fail(form);
    const std::vector<ConfigNode> row = rows[i].elements();
    for (int j = 0; j < 3; ++j) {
      const double v = row[j].asDouble();
      if (!(v >= 0.0)) row[j].fail("must be >= 0 (got " + shortest(v) + ")");
      m[j][i] = v;
    }
  }
  for (int j = 0; j < 3; ++j) {
    const double sum = m[j][0] + m[j][1] + m[j][2];
    // A little over 1 for the rounding of decimal entries (0.1 + 0.2 + 0.7).
    if (sum > 1.0 + 1e-12) {
      char text[32];
      std::snprintf(text, sizeof text, "%.6g", sum);
      n.fail(std::string("column ") + kChannel[j] + " (light absorbed in " + kChannel[j] +
             ") sums to " + text + ": re-emission cannot add light (each column at most 1)");
    }
  }
  return m;
}

physics::ResponseKernel parseModel(const ConfigNode& n, ScatteringDelayConfig& out) {
  const std::string model = n.requireString("model");
  bool known = false;
  for (const ModelKeys& m : kModels) known = known || model == m.model;
  if (!known) n.failKey("model", "must be exponential, gaussian or table (got '" + model + "')");
  refuseOtherModelsKeys(n, model);
  physics::ResponseKernel k;
  if (model == "exponential") {
    k.model = ResponseModel::Exponential;
    k.lifetime_s = duration(n, "lifetime", true);
  } else if (model == "gaussian") {
    k.model = ResponseModel::Gaussian;
    k.mean_s = duration(n, "mean", false);
    k.sigma_s = duration(n, "sigma", true);
  } else {  // table
    k = parseResponseTable(n);
    out.table_file = configRelativePath(n, n.requireString("file")).string();
    out.delay_unit = n.getString("delay_unit", "s");
  }
  return k;
}

}  // namespace

ScatteringDelayConfig parseScatteringDelay(const ConfigNode& parent, const TimeAxis& axis) {
  const char* form = "must be a mapping {model: exponential, gaussian or table, ...} or none";
  const ConfigNode n = parent.child("scattering_delay");
  ScatteringDelayConfig out;
  if (n.isScalar()) {
    if (n.asString() != "none") n.fail(std::string(form) + " (got '" + n.asString() + "')");
    return out;
  }
  if (!n.isMap()) n.fail(form);
  physics::ResponseKernel k = parseModel(n, out);
  k.fraction = n.getDouble("fraction", 1.0);
  if (!(k.fraction >= 0.0 && k.fraction <= 1.0)) {
    n.failKey("fraction", "must be in [0, 1] (got " + shortest(k.fraction) + ")");
  }
  if (const auto reemission = n.optionalChild("reemission"))
    k.reemission = parseReemission(*reemission);
  // The filter on this axis: a Gaussian's 16 sigma or a table's extent must
  // fit the stage's kMaxResponseTaps bins.
  try {
    (void)physics::responseTaps(k, axis.bin_width_s);
  } catch (const std::invalid_argument& e) {
    n.fail(std::string(e.what()) + " at time.bin_width " + readableDuration(axis.bin_width_s) +
           " (a wider bin or a shorter kernel)");
  }
  out.kernel = std::move(k);
  return out;
}

void parseMaterials(const ConfigNode& node, RunConfig& config) {
  if (!node.isMap())
    node.fail("expected a mapping of glTF material name -> {scattering_delay: ...}");
  config.materials_at = node.location();
  for (const std::string& name : node.keys()) {
    if (!node.has(name)) node.failKey(name, "expected {scattering_delay: ...} (got nothing)");
    const ConfigNode entry = node.child(name);
    if (!entry.isMap()) entry.fail("expected a mapping {scattering_delay: ...}");
    MaterialConfig m;
    m.name = name;
    m.at = entry.location();
    m.scattering_delay = parseScatteringDelay(entry, config.render.time);
    config.materials.push_back(std::move(m));
  }
}

namespace {
YAML::Node durationNode(double s) { return YAML::Node(durationText(s)); }

YAML::Node scatteringDelayNode(const ScatteringDelayConfig& d) {
  if (!d.kernel) return YAML::Node("none");
  const physics::ResponseKernel& k = *d.kernel;
  YAML::Node n;
  switch (k.model) {
    case ResponseModel::Exponential:
      n["model"] = "exponential";
      n["lifetime"] = durationNode(k.lifetime_s);
      break;
    case ResponseModel::Gaussian:
      n["model"] = "gaussian";
      n["mean"] = durationNode(k.mean_s);
      n["sigma"] = durationNode(k.sigma_s);
      break;
    case ResponseModel::Table:
      n["model"] = "table";
      n["file"] = d.table_file;
      n["delay_unit"] = d.delay_unit;
      break;
  }
  n["fraction"] = shortest(k.fraction);
  YAML::Node rows(YAML::NodeType::Sequence);
  for (int i = 0; i < 3; ++i) {
    YAML::Node row(YAML::NodeType::Sequence);
    for (int j = 0; j < 3; ++j) row.push_back(shortest(k.reemission[j][i]));
    row.SetStyle(YAML::EmitterStyle::Flow);
    rows.push_back(row);
  }
  rows.SetStyle(YAML::EmitterStyle::Flow);
  n["reemission"] = rows;
  return n;
}
}  // namespace

YAML::Node materialsNode(const std::vector<MaterialConfig>& materials) {
  YAML::Node n(YAML::NodeType::Map);
  for (const MaterialConfig& m : materials) {
    YAML::Node entry;
    entry["scattering_delay"] = scatteringDelayNode(m.scattering_delay);
    n[m.name] = entry;
  }
  return n;
}

}  // namespace tofsim::config
