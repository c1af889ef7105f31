#pragma once
// Virtual point lights from a reflective shadow map (Dachsbacher and
// Stamminger 2005) rendered from the light: each RSM texel that sees a lit
// surface becomes a VPL (Eq. 17). The texel's solid angle Omega gives the
// flux it receives, Phi = I * profile * Omega; the surface reflects it
// diffusely, so the VPL is a cosine emitter of intensity
// albedo * Phi / pi * cos(theta), emitting at t_l = eta * |l - x_l| / c.
// With render.materials: gltf it keeps Phi, the direction to the light and
// its material, and emits by its BRDF (ir::rsmTexelVpl).

#include <glm/glm.hpp>
#include <vector>

#include "tofsim/capture/Light.h"
#include "tofsim/capture/Medium.h"
#include "tofsim/ir/IrBackend.h"

namespace tofsim::render {

class GpuScene;

using ir::Vpl;  // matches struct Vpl in shaders/vpl.glsl (std430)

/// Spot lights narrower than 60 degrees (half angle) use one view of side
/// `rsmResolution` covering the cone; wider spots and point lights use six
/// cube faces of that side. VPLs are in texel order, faces in +X..-Z order.
/// `vertexModel` (ir::vertexModelOf render.materials): the surfaces' vertices
/// (glTF: glossy VPLs, from the RSM's metallic and roughness too;
/// ir::rsmTexelVpl). `edgeSamples`
/// (render.indirect.rsm_edge_samples): the texels at edges from a finer RSM
/// of the view (ir::rsmViewVpls). `medium`: the one filling the scene, which
/// attenuates each VPL's light -> VPL leg (ir::attenuateLightLegs).
std::vector<Vpl> generateVpls(const GpuScene& scene, const capture::Light& light, int rsmResolution,
                              int edgeSamples, double indexOfRefraction, const glm::vec3& boundsMin,
                              const glm::vec3& boundsMax, int vertexModel,
                              const capture::Medium& medium = capture::Medium{});

}  // namespace tofsim::render
