#pragma once
// render.indirect.rsm_edge_samples: the RSM's texels at edges, sampled finer.
//
// A texel becomes one VPL at the surface its centre sees, with the flux of the
// texel's whole solid angle. Where the texel straddles an edge that is wrong in
// energy, not only in position: at a silhouette against nothing (the open front
// of a box) the texels whose centre hits carry the flux of the part that
// misses, those whose centre misses drop the part that hits, and where the
// silhouette runs along a texel row (an axis-aligned box seen head-on) the two
// do not cancel: the first bounce's total flux swings by percents with the
// RSM's side (the Cornell box's: -4.2 % at 32^2, +1.6 % at 64^2, -1.0 % at
// 128^2). At a crease the texel's patch reaches through the other surface,
// whose share of the light the near field then clips away (vpl_near_field.glsl).
//
// So a texel at an edge of the RSM (ir::sampledPixels' test on the texels' VPLs:
// a silhouette, a crease or a depth jump in its 3 x 3 neighbourhood) is split
// into N x N sub-texels, each a VPL of the RSM of side N R (rsmTexelVpl, the same
// rays on both backends), and the sub-texels on one flat surface are merged
// into one VPL: the sum of their fluxes, at the member nearest their centroid,
// its patch their bounding box shrunk to their joint area. A texel whose centre misses still makes
// the VPLs of the parts that hit.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "tofsim/ir/IrBackend.h"

namespace tofsim::ir {

/// Largest side of the finer RSM the edge texels are sampled from: the GL
/// backend rasterises the whole view at that side (3 RGBA32F maps, 48 MiB at
/// 2048^2).
constexpr int kMaxRsmEdgeSampleSide = 2048;

/// The sub-texel side N an RSM of side `resolution` takes at its edges:
/// `samples` (render.indirect.rsm_edge_samples), lowered so that N * resolution
/// stays within kMaxRsmEdgeSampleSide; 1 = no sub-texels.
int rsmEdgeSamples(int samples, int resolution);

/// One view's texels at side R, row-major from the bottom row (as GL stores
/// them): their VPLs (rsmTexelVpl) in texel order, and for each texel the
/// index of its VPL, -1 where it makes none (4 bytes a texel, not a VPL's
/// 112: an NLOS light's five views at side 4096 are mostly empty).
struct TexelVpls {
  std::vector<Vpl> vpls;
  std::vector<int32_t> index;

  explicit TexelVpls(int resolution)
      : index(static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution), -1) {}
  /// Texel t's VPL, texels added in increasing order.
  void add(std::size_t t, const Vpl& vpl) {
    index[t] = static_cast<int32_t>(vpls.size());
    vpls.push_back(vpl);
  }
};

/// 1 for each texel at an edge: ir::sampledPixels' test on the texels' VPLs'
/// positions and normals, a texel without a VPL counting as background.
std::vector<uint8_t> rsmEdgeTexels(const TexelVpls& texels, int resolution);

/// The VPLs of one texel from its n x n sub-texels' VPLs (row-major): one per
/// flat surface among them (onFlatSurface with the first sub-texel of each),
/// in the order of those first sub-texels.
std::vector<Vpl> mergeSubTexelVpls(const std::vector<std::optional<Vpl>>& subTexels, int n);

/// For the edge texels (their flags as rsmEdgeTexels gives them), the VPLs of
/// each one's n x n sub-texels in the RSM of side n R, n^2 per edge texel in
/// texel order.
using SubTexelSource =
    std::function<std::vector<std::optional<Vpl>>(const std::vector<uint8_t>& edges, int n)>;

/// A view's VPLs in texel order: a texel's own VPL, or at an edge with n > 1
/// its merged sub-texels' (mergeSubTexelVpls), from `subTexels` (called once,
/// only when some texel is an edge).
std::vector<Vpl> rsmViewVpls(TexelVpls texels, int resolution, int n,
                             const SubTexelSource& subTexels);

}  // namespace tofsim::ir
