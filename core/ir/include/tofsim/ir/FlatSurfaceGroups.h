#pragma once
// The cells of an n x n grid of samples (an RSM texel's sub-texels, a pixel's
// samples) grouped by the flat surface they see, for merging each group into
// one: ir::mergeSubTexelVpls (render.indirect.rsm_edge_samples) and the CPU
// gather's merged pixel samples (render.indirect.merge_pixel_samples). Each
// cell is tested against its group's first (onFlatSurface), in scan order, so
// every backend groups alike. The merged sample sits at the member nearest
// the group's centroid, a point of the surface; its footprint is one cell's
// stretched to the group's bounding box and shrunk to its area, so that a
// strip along a crease keeps its width instead of reaching through the other
// surface as a square of its area would.

#include <glm/glm.hpp>
#include <optional>
#include <vector>

namespace tofsim::ir {

/// What a cell sees: a surface point and its unit normal.
struct CellSurface {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};
};

struct FlatSurfaceGroup {
  std::vector<int> cells;  ///< row-major cell indices, increasing
  int nearest = 0;         ///< the cell nearest the centroid, the first of equals
  /// Factors for one cell's steps along the columns (x) and rows (y): the
  /// group's bounding box in cells, times sqrt(cells / its area).
  glm::vec2 stretch{1.0f};
};

/// The groups of the n x n cells (row-major; nothing where a cell sees no
/// surface), in the order of their first cells.
std::vector<FlatSurfaceGroup> flatSurfaceGroups(const std::vector<std::optional<CellSurface>>& cells,
                                                int n);

}  // namespace tofsim::ir
