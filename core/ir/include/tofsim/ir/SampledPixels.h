#pragma once
// render.adaptive_pixel_samples: which pixels take their N x N sub-pixel
// samples. The footprint of one centre sample extrapolates the centre's
// tangent plane over the whole pixel (footprint_kernel.md); that holds where
// the pixel's neighbourhood is that plane and fails at silhouettes, creases
// and the border of the background, the pixels the sub-samples are for. The
// test reads only the pixel-centre G-buffer both backends return, so they
// sample the same pixels.

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "tofsim/ir/IrBackend.h"

namespace tofsim::ir {

/// Largest angle, in degrees, between a pixel's tangent plane and the
/// direction to a neighbour's centre point, and between their normals, for
/// the neighbour to count as the same flat surface.
constexpr float kFlatNeighbourAngle_deg = 5.0f;

/// Whether the point q with unit normal m lies on the flat surface through p
/// with unit normal n: within kFlatNeighbourAngle_deg of its tangent plane
/// (seen from p) and with a normal turned by at most that angle. Also the
/// RSM's test for texels and sub-texels on one surface (RsmEdgeTexels.h).
bool onFlatSurface(const glm::vec3& p, const glm::vec3& n, const glm::vec3& q, const glm::vec3& m);

/// One entry per pixel (row-major, row 0 at the top): 1 where any of the 8
/// neighbours' centre points (those inside the image) lies off the pixel's
/// tangent plane or has a turned normal, or where a surface pixel borders
/// background or a background pixel borders a surface, or, given `lit` (one
/// entry per pixel, LitPixels.h), where the light reaches one of two
/// neighbouring surface pixels' centres and not the other's (a shadow's edge,
/// a hard spot's rim); 0 elsewhere.
std::vector<uint8_t> sampledPixels(const CentreSurfaces& surfaces, int32_t width, int32_t height,
                                   const std::vector<uint8_t>& lit = {});

}  // namespace tofsim::ir
