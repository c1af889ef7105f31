#include "NlosConfigParser.h"

#include <cmath>
#include <string>

#include "FieldParse.h"
#include "NlosFields.h"
#include "ShortestNumber.h"

namespace tofsim::config {

const char* nlosScanName(NlosScan scan) {
  return sensors::nameOf(sensors::Choice<NlosScan>{kNlosScanNames}, scan);
}

namespace {

std::array<int32_t, 2> gridOf(const ConfigNode& node, const char* key,
                              std::array<int32_t, 2> fallback) {
  const std::vector<double> v = node.getDoubles(key, 2, {double(fallback[0]), double(fallback[1])});
  for (double d : v) {
    if (!(d >= 1 && d <= 4096 && d == std::floor(d))) {
      node.failKey(key, "must be two integers in [1, 4096] (points along x, y)");
    }
  }
  return {static_cast<int32_t>(v[0]), static_cast<int32_t>(v[1])};
}

glm::vec2 uvOf(const ConfigNode& node, const std::vector<double>& v, const char* key) {
  for (double d : v) {
    if (!(d >= 0.0 && d <= 1.0)) node.failKey(key, "each coordinate must be in [0, 1]");
  }
  return {static_cast<float>(v[0]), static_cast<float>(v[1])};
}

glm::vec3 requireVec3(const ConfigNode& node, const char* key) {
  if (!node.has(key)) node.failKey(key, "required key is missing ([x, y, z] in metres)");
  const std::vector<double> v = node.getDoubles(key, 3, {});
  for (double d : v) {
    if (!std::isfinite(d)) node.failKey(key, "must be finite");
  }
  return glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}

void parseAperture(const ConfigNode& node, NlosConfig& out) {
  if (!node.has("laser_aperture")) return;
  const ConfigNode a = node.child("laser_aperture");
  const std::vector<ConfigNode> corners = a.isSequence() ? a.elements() : std::vector<ConfigNode>{};
  if (corners.size() != 2 || !corners[0].isSequence() || !corners[1].isSequence()) {
    a.fail("expected [[u0, v0], [u1, v1]]");
  }
  auto corner = [&](const ConfigNode& c) {
    std::vector<double> v;
    for (const ConfigNode& e : c.elements()) v.push_back(e.asDouble());
    if (v.size() != 2) c.fail("expected [u, v]");
    return uvOf(node, v, "laser_aperture");
  };
  out.laser_aperture_start = corner(corners[0]);
  out.laser_aperture_end = corner(corners[1]);
  if (!(out.laser_aperture_start.x < out.laser_aperture_end.x &&
        out.laser_aperture_start.y < out.laser_aperture_end.y)) {
    node.failKey("laser_aperture", "must have u0 < u1 and v0 < v1");
  }
}

void parseCustom(const ConfigNode& node, const std::string& key, NlosConfig& out) {
  if (key == "sensor_grid") {
    out.sensor_grid = gridOf(node, "sensor_grid", out.sensor_grid);
  } else if (key == "laser_grid") {
    out.laser_grid = gridOf(node, "laser_grid", out.laser_grid);
  } else if (key == "laser_point") {
    out.laser_point =
        uvOf(node, node.getDoubles("laser_point", 2, {out.laser_point.x, out.laser_point.y}),
             "laser_point");
  } else if (key == "laser_aperture") {
    parseAperture(node, out);
  } else if (key == "sensor_origin") {
    out.sensor_origin = requireVec3(node, "sensor_origin");
    out.sensor_origin_at = node.locationOf("sensor_origin");
  } else if (key == "laser_origin") {
    out.laser_origin = requireVec3(node, "laser_origin");
    out.laser_origin_at = node.locationOf("laser_origin");
  } else if (key == "laser_power") {
    if (node.has("laser_power") && node.child("laser_power").isScalar()) {
      out.laser_power_W = glm::vec3(static_cast<float>(node.getDouble("laser_power", 1.0)));
    } else {
      const std::vector<double> v = node.getDoubles("laser_power", 3, {1.0, 1.0, 1.0});
      out.laser_power_W =
          glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
    }
    for (int c = 0; c < 3; ++c) {
      if (!(out.laser_power_W[c] >= 0.0f && std::isfinite(out.laser_power_W[c]))) {
        node.failKey("laser_power", "must be finite and >= 0 W");
      }
    }
  }
}

}  // namespace

NlosConfig parseNlos(const ConfigNode& node) {
  if (!node.isMap()) node.fail("expected a mapping (relay_wall, scan, sensor_grid, ...)");
  NlosConfig out;
  parseFields(node, kNlosFields, out, [&](const char* key) { parseCustom(node, key, out); });
  if (out.relay_wall.empty()) node.failKey("relay_wall", "required: the relay wall's node name");
  out.relay_wall_at = node.locationOf("relay_wall");
  if (out.scan != NlosScan::Exhaustive) {
    for (const char* key : {"laser_grid", "laser_aperture"}) {
      if (node.has(key)) node.failKey(key, "applies to `scan: exhaustive` only");
    }
  }
  if (out.scan != NlosScan::Single && node.has("laser_point")) {
    node.failKey("laser_point", "applies to `scan: single` only");
  }
  return out;
}

}  // namespace tofsim::config
