#pragma once
// VPLs of a light by rays cast from it over the texel grid of the GL's
// reflective shadow map (core/render/src/Vpls.cpp): the same views (one for a
// spot of at most 60 degrees half angle, else six cube faces +X..-Z), the same
// texel centres, solid angle and flux, the same order. A ray through a texel
// centre finds the surface the rasterizer samples there, so the two lists
// differ only where a triangle edge crosses a texel centre (the rasterizer's
// tie rule) and in float rounding of the hit point. Unlike the GL, surfaces
// closer to the light than its near plane (1e-4 of the scene's far distance)
// are not clipped. `vertexModel`: the surfaces' (ir::rsmTexelVpl). `lit`: texels whose
// ray misses this box trace no ray (LitBounds.h). `edgeSamples`
// (render.indirect.rsm_edge_samples): the texels at edges from their
// sub-texels' rays (ir::rsmViewVpls). `classes`: each VPL's response class
// (ir::setFirstBounceClasses; null: none).

#include <optional>
#include <vector>

#include "tofsim/capture/Light.h"
#include "tofsim/capture/Medium.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/physics/ResponseClassTable.h"
#include "tofsim/rays/RayScene.h"

namespace tofsim::cpu {

std::vector<ir::Vpl> traceRsmVpls(const rays::RayScene& scene, const capture::Light& light,
                                  int rsmResolution, int edgeSamples, double indexOfRefraction,
                                  int vertexModel, int threads,
                                  const std::optional<scene::Bounds>& lit = std::nullopt,
                                  const physics::ResponseClassTable* classes = nullptr,
                                  const capture::Medium& medium = capture::Medium{});

}  // namespace tofsim::cpu
