#include "tofsim/volume/TimeAxis.h"

#include <cmath>

#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim {

int32_t TimeAxis::binOf(double t_s) const {
  const double f = std::floor((t_s - start_s) / bin_width_s);
  if (f >= static_cast<double>(bins)) return kAfterAxis;
  if (!(f >= 0.0)) return kBeforeAxis;
  return static_cast<int32_t>(f);
}

double TimeAxis::start_m() const { return start_s * kSpeedOfLight_m_per_s; }
double TimeAxis::bin_width_m() const { return bin_width_s * kSpeedOfLight_m_per_s; }

double TimeAxis::speedOfLight_m_per_s() const {
  return kSpeedOfLight_m_per_s / index_of_refraction;
}

double TimeAxis::depthPerSecond_m_per_s() const {
  const double legs = camera_unwarp ? 1.0 : 2.0;
  return speedOfLight_m_per_s() / legs;
}

}  // namespace tofsim
