#include "RunSections.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "FieldParse.h"
#include "LightFields.h"
#include "OutputFields.h"
#include "RunFields.h"
#include "TimeFields.h"

namespace tofsim::config {

const char* irBackendName(IrBackendKind kind) {
  return sensors::nameOf(Choice<IrBackendKind>{kIrBackendNames}, kind);
}

void parseLight(const ConfigNode& node, LightConfig& out) {
  parseFields(node, kLightFields, out);
  capture::Light& l = out.light;
  if (glm::length(l.direction_world) <= 0.0f) node.failKey("direction", "must not be zero");
  l.direction_world = glm::normalize(l.direction_world);
  if (!(l.cone_falloff_deg >= 0.0f && l.cone_falloff_deg <= l.cone_half_angle_deg)) {
    node.failKey("cone_falloff", "must be in [0, cone_angle]");
  }
}

void parseTime(const ConfigNode& node, TimeAxis& time) {
  // One place for both: the renderers and the sensors (depth = (c / eta) t /
  // legs) read the axis's.
  parseFields(node, kTimeFields, time);
}

void parseRender(const ConfigNode& node, RunConfig& out) {
  parseFields(node, kRenderFields, out, [&](const std::string& key) {
    if (const auto section = node.optionalChild(key)) {
      if (key == "indirect") parseFields(*section, kIndirectFields, out.render.indirect);
      if (key == "reference") parseFields(*section, kReferenceFields, out.reference);
    }
  });
}

namespace {

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

void parseComponents(const ConfigNode& components, const RunConfig& config, OutputConfig& o) {
  for (const ConfigNode& c : components.elements()) {
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

void parsePlotRanges(const ConfigNode& ranges, OutputConfig& o) {
  if (!ranges.isMap()) {
    ranges.fail("expected a mapping of picture name -> [lo, hi]");
  }
  for (const std::string& name : ranges.keys()) {
    // A key without a value (`depth:`) is listed but not `has` (found by
    // fuzz_sequence: r[0] of no values).
    if (!ranges.has(name)) ranges.failKey(name, "must be [lo, hi] with lo < hi (got nothing)");
    const std::vector<double> r = ranges.getDoubles(name, 2, {});
    if (!(std::isfinite(r[0]) && std::isfinite(r[1]) && r[0] < r[1])) {
      ranges.failKey(name, "must be [lo, hi] with lo < hi");
    }
    o.plot_ranges[name] = {r[0], r[1]};
  }
}

}  // namespace

void parseOutput(const ConfigNode& node, const RunConfig& config, OutputConfig& o) {
  // The lists are read after the other keys, as they always were (the
  // first error a config with several reports stays the same).
  parseFields(node, kOutputFields, o);
  if (const auto ranges = node.optionalChild("plot_ranges")) parsePlotRanges(*ranges, o);
  if (const auto components = node.optionalChild("components")) {
    parseComponents(*components, config, o);
  }
}

}  // namespace tofsim::config
