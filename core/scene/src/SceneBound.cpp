#include "tofsim/scene/SceneBound.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tofsim::scene {

std::string sceneBoundText(const glm::dvec3& p) {
  double reach = 0.0;
  for (int i = 0; i < 3; ++i) {
    reach = std::isnan(p[i]) ? p[i] : std::max(reach, std::fabs(p[i]));
    if (std::isnan(reach)) break;
  }
  char text[80];
  std::snprintf(text, sizeof text, "%.3g m from the origin (at most %.3g m)", reach,
                kMaxSceneCoordinate_m);
  return text;
}

}  // namespace tofsim::scene
