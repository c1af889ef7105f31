#include "MergedSamples.h"

#include <optional>

#include "tofsim/ir/FlatSurfaceGroups.h"

namespace tofsim::cpu {

void mergePixelSamples(const PixelSurface* samples, const unsigned char* lit, int n,
                       std::vector<PixelSurface>& out) {
  std::vector<std::optional<ir::CellSurface>> cells(static_cast<std::size_t>(n) * n);
  for (std::size_t s = 0; s < cells.size(); ++s) {
    if (lit[s]) cells[s] = ir::CellSurface{samples[s].x, samples[s].n};
  }
  for (const ir::FlatSurfaceGroup& g : ir::flatSurfaceGroups(cells, n)) {
    if (g.cells.size() == 1) {
      out.push_back(samples[g.nearest]);  // a lone sample is itself
      continue;
    }
    PixelSurface merged = samples[g.nearest];
    merged.brdf = glm::vec3(0.0f);
    merged.weight = 0.0f;
    for (int s : g.cells) {
      merged.brdf += samples[s].brdf;
      merged.weight += samples[s].weight;
    }
    merged.dxdu *= g.stretch.x;
    merged.dxdv *= g.stretch.y;
    out.push_back(merged);
  }
}

}  // namespace tofsim::cpu
