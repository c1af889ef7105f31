#include "tofsim/ir/FlatSurfaceGroups.h"

#include <algorithm>
#include <cmath>

#include "tofsim/ir/SampledPixels.h"
#include "tofsim/util/Error.h"

namespace tofsim::ir {

std::vector<FlatSurfaceGroup> flatSurfaceGroups(const std::vector<std::optional<CellSurface>>& cells,
                                                int n) {
  TOFSIM_CHECK_EQ(cells.size(), static_cast<std::size_t>(n) * n);
  std::vector<FlatSurfaceGroup> groups;
  for (int s = 0; s < n * n; ++s) {
    if (!cells[s]) continue;
    auto group = std::find_if(groups.begin(), groups.end(), [&](const FlatSurfaceGroup& g) {
      const CellSurface& first = *cells[g.cells.front()];
      return onFlatSurface(first.position, first.normal, cells[s]->position, cells[s]->normal);
    });
    if (group == groups.end()) {
      groups.push_back({{s}});
    } else {
      group->cells.push_back(s);
    }
  }
  for (FlatSurfaceGroup& g : groups) {
    double cx = 0.0, cy = 0.0;
    int x0 = n, x1 = 0, y0 = n, y1 = 0;
    for (int s : g.cells) {
      cx += s % n, cy += s / n;
      x0 = std::min(x0, s % n), x1 = std::max(x1, s % n);
      y0 = std::min(y0, s / n), y1 = std::max(y1, s / n);
    }
    const auto count = static_cast<double>(g.cells.size());
    cx /= count, cy /= count;
    double best = INFINITY;
    for (int s : g.cells) {
      const double d = (s % n - cx) * (s % n - cx) + (s / n - cy) * (s / n - cy);
      if (d < best) best = d, g.nearest = s;
    }
    const float columns = static_cast<float>(x1 - x0 + 1), rows = static_cast<float>(y1 - y0 + 1);
    const float fill = std::sqrt(static_cast<float>(g.cells.size()) / (columns * rows));
    g.stretch = glm::vec2(columns * fill, rows * fill);
  }
  return groups;
}

}  // namespace tofsim::ir
