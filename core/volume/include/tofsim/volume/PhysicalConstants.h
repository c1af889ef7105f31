#pragma once

namespace tofsim {

/// Speed of light in vacuum, m/s (exact by SI definition).
inline constexpr double kSpeedOfLight_m_per_s = 299792458.0;

}  // namespace tofsim
