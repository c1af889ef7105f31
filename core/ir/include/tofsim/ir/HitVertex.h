#pragma once
// The one place a traced hit becomes a scattering vertex: the CPU's surface
// samples (traceSurfaces), its RSM VPLs (cpu::traceRsmVpls), the later
// bounces' VPLs (traceBounce) and the reference take it from here: the hit's
// material's entry of the table (materialVertices) with what its textures
// give at the hit (physics::texturedVertex), as GL's gathers take a G-buffer
// texel's.

#include <vector>

#include "tofsim/physics/ScatterVertex.h"
#include "tofsim/rays/RayScene.h"

namespace tofsim::ir {

/// The vertex of `hit`, whose material's vertex is materials[hit.material]
/// (materialVertices of the traced scene).
inline physics::ScatterVertex hitVertex(const rays::SurfaceHit& hit,
                                        const std::vector<physics::ScatterVertex>& materials) {
  return physics::texturedVertex(materials.at(static_cast<std::size_t>(hit.material)),
                                 hit.baseColorTexel, hit.metallicRoughnessTexel);
}

}  // namespace tofsim::ir
