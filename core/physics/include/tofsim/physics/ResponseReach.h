#pragma once
// How far past its arrival a delayed vertex's light reaches, for time-axis
// advice (`tofsim validate`'s suggested window, apps/pipeline AxisReport):
// the delay beyond which at most `epsilon` of the light scattered there
// arrives. Exponential: the delayed share f has f exp(-t / tau) past t, so
// tau ln(f / epsilon); Gaussian: mean + 4 sigma (3e-5 of it beyond); table:
// its last delay (nothing beyond). 0 when f <= epsilon (the prompt share is
// not delayed).

#include <cmath>

#include "tofsim/physics/TemporalResponse.h"

namespace tofsim::physics {

inline double responseReach_s(const ResponseKernel& kernel, double epsilon) {
  if (!(kernel.fraction > epsilon)) return 0.0;
  switch (kernel.model) {
    case ResponseModel::Exponential:
      return kernel.lifetime_s * std::log(kernel.fraction / epsilon);
    case ResponseModel::Gaussian:
      return kernel.mean_s + 4.0 * kernel.sigma_s;
    case ResponseModel::Table:
      return kernel.tableDelay_s.empty() ? 0.0 : kernel.tableDelay_s.back();
  }
  return 0.0;
}

}  // namespace tofsim::physics
