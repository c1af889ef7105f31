#pragma once
// Private to the config module: numbers as text in their shortest form that
// reads back to the same value (std::to_chars), for the effective config and
// for error messages: 0.3, not 0.29999999999999999; -1e-12, not -0.000000.

#include <charconv>
#include <string>

namespace tofsim::config {

inline std::string shortest(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

/// A float's own shortest form (0.3f -> "0.3"), which reads back to the same float.
inline std::string shortest(float value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace tofsim::config

namespace tofsim::config {

/// `value` (in base units) written as "<number> <unit>" with the number in
/// `unit` = `scale` base units when that reads back to exactly `value`
/// (parse multiplies by `scale`), else in the base unit: "10 ps" for 1e-11 s,
/// never a rounded value.
inline std::string withUnit(double value, double scale, const char* unit, const char* baseUnit) {
  const std::string scaled = shortest(value / scale);
  if (std::stod(scaled) * scale == value) return scaled + " " + unit;
  return shortest(value) + " " + baseUnit;
}

}  // namespace tofsim::config
