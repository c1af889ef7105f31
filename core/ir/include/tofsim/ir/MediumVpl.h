#pragma once
// A VPL at a point of the medium filling the scene (issue 42, item 4): where
// the light's path (from the light, or from a parent VPL) scatters in the
// medium instead of reaching a surface. It has no normal (zero: no side,
// physics::vplEmitterCosine is 1 toward every x), no patch (a point VPL:
// the gathers bound its 1/d^2 by render.indirect's geometry clamp, as a
// later bounce's surface VPL), and scatters by the medium's phase function:
// its vertex is physics::mediumVertex(albedo, phase, g), so vplScatter gives
// albedo x phase(dot(-incoming, toX)), and its flux is never the scatter's
// (vplFluxHoldsScatter is false for a medium vertex, isotropic or not).

#include <glm/glm.hpp>

#include "tofsim/capture/Medium.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/physics/ScatterVertex.h"

namespace tofsim::ir {

/// The medium VPL at `x`, `path_m` the optical path from the light (eta
/// included), `extinguished_W` the power per channel its event stands for
/// (the light extinguished there: absorbed or scattered; the vertex's albedo
/// sigma_s / sigma_t keeps the scattered share), `incoming` the unit
/// direction toward where that light came from, `responseClass` its parent's
/// class (Vpl::flux.w; the medium adds no delay).
inline Vpl mediumVpl(glm::vec3 x, float path_m, glm::vec3 extinguished_W, glm::vec3 incoming,
                     const capture::Medium& medium, float responseClass) {
  Vpl v;
  v.positionPath = glm::vec4(x, path_m);
  v.normal = glm::vec4(0.0f);
  v.flux = glm::vec4(extinguished_W, responseClass);
  v.incoming = glm::vec4(incoming, 0.0f);
  v.vertex = physics::mediumVertex(medium.albedo(), medium.phase, medium.g);
  return v;
}

/// Whether the gathers read each VPL's `incoming` and `vertex` (GL: the VPL
/// buffer holds whole records, vpl.glsl's VPL_VERTICES): where some VPL's
/// scatter may not be in its flux, a glTF surface's (render.materials:
/// gltf) or a medium VPL's (a scattering medium).
inline bool vplsCarryVertex(const capture::RenderSettings& settings) {
  return settings.materials == capture::MaterialModel::Gltf || settings.medium.scatters();
}

/// Whether `v` is a medium VPL (its normal is zero).
inline bool isMediumVpl(const Vpl& v) { return glm::vec3(v.normal) == glm::vec3(0.0f); }

}  // namespace tofsim::ir
