#include "tofsim/ir/RsmEdgeTexels.h"

#include <algorithm>
#include <cmath>

#include "tofsim/ir/FlatSurfaceGroups.h"
#include "tofsim/ir/SampledPixels.h"
#include "tofsim/util/Error.h"

namespace tofsim::ir {

int rsmEdgeSamples(int samples, int resolution) {
  TOFSIM_CHECK(samples >= 1 && resolution >= 1);
  return std::max(1, std::min(samples, kMaxRsmEdgeSampleSide / resolution));
}

std::vector<uint8_t> rsmEdgeTexels(const TexelVpls& texels, int resolution) {
  const std::size_t count = static_cast<std::size_t>(resolution) * resolution;
  TOFSIM_CHECK_EQ(texels.index.size(), count);
  // sampledPixels' test, visited from the texels with a VPL only: an NLOS
  // light's views are mostly empty, and an empty texel is an edge exactly
  // when a neighbour has a VPL (RsmEdgeTexelsTest checks the two agree).
  std::vector<uint8_t> edges(count, 0);
  for (int y = 0; y < resolution; ++y) {
    for (int x = 0; x < resolution; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * resolution + x;
      if (texels.index[p] < 0) continue;
      const Vpl& v = texels.vpls[static_cast<std::size_t>(texels.index[p])];
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= resolution || ny >= resolution) {
            continue;
          }
          const std::size_t q = static_cast<std::size_t>(ny) * resolution + nx;
          if (texels.index[q] < 0) {
            edges[p] = edges[q] = 1;  // a silhouette: both sides
            continue;
          }
          const Vpl& w = texels.vpls[static_cast<std::size_t>(texels.index[q])];
          if (!onFlatSurface(glm::vec3(v.positionPath), glm::vec3(v.normal),
                             glm::vec3(w.positionPath), glm::vec3(w.normal))) {
            edges[p] = 1;
          }
        }
      }
    }
  }
  return edges;
}

std::vector<Vpl> mergeSubTexelVpls(const std::vector<std::optional<Vpl>>& subTexels, int n) {
  TOFSIM_CHECK_EQ(subTexels.size(), static_cast<std::size_t>(n) * n);
  std::vector<std::optional<CellSurface>> cells(subTexels.size());
  for (std::size_t s = 0; s < subTexels.size(); ++s) {
    if (subTexels[s]) {
      cells[s] = CellSurface{glm::vec3(subTexels[s]->positionPath), glm::vec3(subTexels[s]->normal)};
    }
  }
  std::vector<Vpl> vpls;
  for (const FlatSurfaceGroup& g : flatSurfaceGroups(cells, n)) {
    glm::vec3 flux(0.0f);
    for (int s : g.cells) flux += glm::vec3(subTexels[s]->flux);
    Vpl vpl = *subTexels[g.nearest];
    vpl.flux = glm::vec4(flux, vpl.flux.w);  // w: the nearest's response class (VplClasses.h)
    vpl.patchU *= g.stretch.x;  // the patch of the group's sub-texels
    vpl.patchV *= g.stretch.y;
    vpls.push_back(vpl);
  }
  return vpls;
}

std::vector<Vpl> rsmViewVpls(TexelVpls texels, int resolution, int n,
                             const SubTexelSource& subTexels) {
  if (n == 1) return std::move(texels.vpls);
  const std::vector<uint8_t> edges = rsmEdgeTexels(texels, resolution);
  if (std::find(edges.begin(), edges.end(), 1) == edges.end()) return std::move(texels.vpls);
  const std::vector<std::optional<Vpl>> subs = subTexels(edges, n);
  const auto perTexel = static_cast<std::ptrdiff_t>(n) * n;
  std::vector<Vpl> vpls;
  auto sub = subs.begin();  // the next edge texel's sub-texels
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (edges[i]) {
      TOFSIM_CHECK(subs.end() - sub >= perTexel);
      const std::vector<Vpl> merged =
          mergeSubTexelVpls(std::vector<std::optional<Vpl>>(sub, sub + perTexel), n);
      vpls.insert(vpls.end(), merged.begin(), merged.end());
      sub += perTexel;
    } else if (texels.index[i] >= 0) {
      vpls.push_back(texels.vpls[static_cast<std::size_t>(texels.index[i])]);
    }
  }
  TOFSIM_CHECK(sub == subs.end());
  return vpls;
}

}  // namespace tofsim::ir
