#pragma once
// The one place a traced hit's material becomes a scattering vertex: the
// CPU's surface samples (traceSurfaces), its RSM VPLs (cpu::traceRsmVpls) and
// the later bounces' VPLs (traceBounce) all take it from here, so a material
// parameter added to the vertex is read from the hit once.

#include "tofsim/physics/ScatterVertex.h"
#include "tofsim/rays/RayScene.h"

namespace tofsim::ir {

/// The vertex of `hit` under material model `model` (physics::VERTEX_*:
/// vertexModelOf render.materials).
inline physics::ScatterVertex hitVertex(const rays::SurfaceHit& hit, int model) {
  return physics::scatterVertex(model, hit.albedo, hit.metallic, hit.roughness);
}

}  // namespace tofsim::ir
