#include "tofsim/config/Units.h"

#include <cctype>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string_view>

#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::config {

namespace {

struct Quantity {
  double value = 0.0;
  std::string unit;
};

Quantity split(const std::string& text) {
  std::size_t consumed = 0;
  Quantity q;
  try {
    q.value = std::stod(text, &consumed);
  } catch (const std::exception&) {
    throw std::invalid_argument("expected a number with an optional unit, got '" + text + "'");
  }
  std::string_view rest(text);
  rest.remove_prefix(consumed);
  while (!rest.empty() && std::isspace(static_cast<unsigned char>(rest.front())))
    rest.remove_prefix(1);
  while (!rest.empty() && std::isspace(static_cast<unsigned char>(rest.back())))
    rest.remove_suffix(1);
  q.unit = std::string(rest);
  if (!std::isfinite(q.value))
    throw std::invalid_argument("value must be finite, got '" + text + "'");
  return q;
}

double scaled(const std::string& text, const std::map<std::string, double, std::less<>>& units,
              const char* kind) {
  const Quantity q = split(text);
  if (q.unit.empty()) return q.value;
  const auto it = units.find(q.unit);
  if (it == units.end()) {
    std::string known;
    for (const auto& [name, factor] : units) known += (known.empty() ? "" : ", ") + name;
    throw std::invalid_argument("unknown " + std::string(kind) + " unit '" + q.unit + "' in '" +
                                text + "' (known: " + known + ")");
  }
  return q.value * it->second;
}

const std::map<std::string, double, std::less<>> kLengthUnits = {
    {"km", 1e3}, {"m", 1.0}, {"cm", 1e-2}, {"mm", 1e-3}, {"um", 1e-6}};

}  // namespace

double parseDuration_s(const std::string& text) {
  static const std::map<std::string, double, std::less<>> units = [] {
    std::map<std::string, double, std::less<>> u = {{"s", 1.0},   {"ms", 1e-3},  {"us", 1e-6},
                                                    {"ns", 1e-9}, {"ps", 1e-12}, {"fs", 1e-15}};
    // A length is an optical path length; light covers it in length / c.
    for (const auto& [name, metres] : kLengthUnits) u[name] = metres / kSpeedOfLight_m_per_s;
    return u;
  }();
  // A bare number was read as seconds, which turned "bin_width: 10" (meant
  // as ps) into one 10 s bin that rendered junk; only 0 needs no unit.
  if (split(text).unit.empty() && split(text).value != 0.0) {
    throw std::invalid_argument("a time needs a unit: write '" + text + " ps', '" + text +
                                " ns', ... (s, ms, us, ns, ps, fs) or an optical path length ('" +
                                text + " mm': the time light takes to cover it)");
  }
  return scaled(text, units, "time");
}

double parseLength_m(const std::string& text) { return scaled(text, kLengthUnits, "length"); }

double parseAngle_deg(const std::string& text) {
  static const std::map<std::string, double, std::less<>> units = {{"deg", 1.0},
                                                                   {"rad", 180.0 / M_PI},
                                                                   {"mrad", 0.18 / M_PI}};
  return scaled(text, units, "angle");
}

double parseBytes(const std::string& text) {
  static const std::map<std::string, double, std::less<>> units = {
      {"B", 1.0},      {"KB", 1e3},        {"MB", 1e6},           {"GB", 1e9},
      {"KiB", 1024.0}, {"MiB", 1048576.0}, {"GiB", 1073741824.0}, {"TiB", 1099511627776.0}};
  return scaled(text, units, "size");
}

double parseAttenuation_per_m(const std::string& text) {
  // A coefficient is a reciprocal length; "/m" and "1/m" alike (the forms
  // optics texts write; turbid water and tissue are quoted per cm or mm).
  static const std::map<std::string, double, std::less<>> units = [] {
    std::map<std::string, double, std::less<>> u;
    for (const auto& [name, metres] : kLengthUnits) {
      u["/" + name] = 1.0 / metres;
      u["1/" + name] = 1.0 / metres;
    }
    return u;
  }();
  return scaled(text, units, "attenuation");
}

double parseFrequency_Hz(const std::string& text) {
  static const std::map<std::string, double, std::less<>> units = {
      {"Hz", 1.0}, {"kHz", 1e3}, {"MHz", 1e6}, {"GHz", 1e9}};
  return scaled(text, units, "frequency");
}

}  // namespace tofsim::config
