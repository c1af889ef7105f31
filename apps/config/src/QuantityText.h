#pragma once
// Private to the config module: values as a config writes them ("100 ps",
// "20 MHz"), for the effective config and the key docs, and a Range as the
// docs and the errors say it ("in [0, 1]", ">= 0").

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "ShortestNumber.h"
#include "tofsim/config/Units.h"
#include "tofsim/sensors/ParamField.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::config {

/// "100 ps": the largest unit giving a magnitude >= 1 that reads back exactly.
inline std::string durationText(double s) {
  if (s == 0.0) return "0 s";
  const std::pair<double, const char*> units[] = {{1.0, "s"},   {1e-3, "ms"},  {1e-6, "us"},
                                                  {1e-9, "ns"}, {1e-12, "ps"}, {1e-15, "fs"}};
  for (const auto& [scale, name] : units) {
    if (std::abs(s) >= scale) return withUnit(s, scale, name, "s");
  }
  return withUnit(s, 1e-15, "fs", "s");
}

/// A time as a config writes it, in the form the user most likely wrote:
/// the shortest of `timeForm` (the time as a duration) and the optical path
/// lengths ("1 cm": the time light takes to cover it, Units.h) that reads
/// back to exactly `s`; `timeForm` on a tie. The effective config of
/// `bin_width: 1 cm` says "1 cm", not "33.35640951981521 ps" (the metadata
/// keeps the seconds); a time written in ps keeps its form.
inline std::string timeText(double s, std::string timeForm) {
  std::string best = std::move(timeForm);
  if (s == 0.0) return best;
  const std::pair<double, const char*> lengths[] = {
      {1e3, "km"}, {1.0, "m"}, {1e-2, "cm"}, {1e-3, "mm"}, {1e-6, "um"}};
  for (const auto& [metres, name] : lengths) {
    const std::string text = shortest(s / (metres / kSpeedOfLight_m_per_s)) + " " + name;
    if (text.size() < best.size() && parseDuration_s(text) == s) best = text;
  }
  return best;
}

/// "-0.5 ps", "1e+300 s": 6 significant digits in the largest unit giving a
/// magnitude >= 1 (fs below), for messages about computed times, which
/// durationText would write with every digit they need to read back.
inline std::string readableDuration(double s) {
  const std::pair<double, const char*> units[] = {
      {1.0, "s"}, {1e-3, "ms"}, {1e-6, "us"}, {1e-9, "ns"}, {1e-12, "ps"}};
  std::pair<double, const char*> unit{1e-15, "fs"};
  for (const auto& u : units) {
    if (std::abs(s) >= u.first) {
      unit = u;
      break;
    }
  }
  char text[48];
  std::snprintf(text, sizeof text, "%.6g %s", s / unit.first, unit.second);
  return text;
}

inline std::string frequencyText(double hz) {
  if (hz >= 1e9) return withUnit(hz, 1e9, "GHz", "Hz");
  if (hz >= 1e6) return withUnit(hz, 1e6, "MHz", "Hz");
  if (hz >= 1e3) return withUnit(hz, 1e3, "kHz", "Hz");
  return shortest(hz) + " Hz";
}

/// "512 MiB": a byte count in the largest binary unit that divides it.
inline std::string bytesText(double bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int u = 0;
  while (u < 6 && bytes >= 1024.0 && std::fmod(bytes, 1024.0) == 0.0) {
    bytes /= 1024.0;
    ++u;
  }
  return shortest(bytes) + " " + units[u];
}

/// "> 0", ">= 0", "in [0, 1]"; "" for any value.
inline std::string rangeText(const sensors::Range& r) {
  if (r.any()) return "";
  const std::string lo = shortest(r.min);
  if (r.max == sensors::kAnyValue.max) return (r.minExclusive ? "> " : ">= ") + lo;
  return std::string("in ") + (r.minExclusive ? "(" : "[") + lo + ", " + shortest(r.max) + "]";
}

}  // namespace tofsim::config
