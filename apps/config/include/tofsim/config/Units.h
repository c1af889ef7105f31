#pragma once
// Quantities with units in config values: "10 ps", "3 ns", "0.5 m", "30 deg",
// "512 MiB", "20 MHz", "0.04 /m". Parsers throw std::invalid_argument with a
// message the config module wraps with the value's location.

#include <string>

namespace tofsim::config {

/// Time in seconds. Accepts s, ms, us, ns, ps, fs, or a length (m, cm, mm, um,
/// km), read as optical path length in vacuum and divided by c. A bare number
/// other than 0 is refused (a unit is needed to tell "10" ps from s).
double parseDuration_s(const std::string& text);
/// Length in metres: m, cm, mm, um, km. A bare number is metres.
double parseLength_m(const std::string& text);
/// Angle in degrees: deg, rad or mrad. A bare number is degrees.
double parseAngle_deg(const std::string& text);
/// Byte count: B, KB, MB, GB, KiB, MiB, GiB, TiB. A bare number is bytes.
double parseBytes(const std::string& text);
/// An attenuation coefficient (a medium's sigma_a, sigma_s) in 1/m: /m, 1/m,
/// /cm, 1/cm, /mm, 1/mm, /km, 1/km, /um, 1/um. A bare number is 1/m.
double parseAttenuation_per_m(const std::string& text);
/// Frequency in hertz: Hz, kHz, MHz, GHz. A bare number is hertz.
double parseFrequency_Hz(const std::string& text);

}  // namespace tofsim::config
