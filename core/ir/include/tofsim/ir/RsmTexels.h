#pragma once
// The reflective shadow map's views and texels, shared by both backends: the
// GL one rasterises each view and reads the surfaces back, the CPU one casts a
// ray per texel; both turn a texel's surface into a VPL here, so they make the
// same VPLs from the same surfaces.

#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "tofsim/capture/Light.h"
#include "tofsim/capture/Medium.h"
#include "tofsim/capture/MediumRegions.h"
#include "tofsim/ir/IrBackend.h"

namespace tofsim::ir {

/// One RSM view from the light: the basis glm::lookAt(l, l + forward, upHint)
/// builds, and the half angle of its square frustum.
struct RsmView {
  glm::vec3 forward{0.0f}, right{0.0f}, up{0.0f};
  glm::vec3 upHint{0.0f};  ///< the up vector given to glm::lookAt
  float halfAngle_rad = 0.0f;
  double tanHalf = 0.0;  ///< tan(halfAngle_rad): once per view, not per texel

  glm::mat4 viewMatrix(const glm::vec3& light_world) const;
};

/// One view for a spot light of half angle up to 60 degrees, else the six cube
/// faces +X, -X, +Y, -Y, +Z, -Z: the VPL order.
std::vector<RsmView> rsmViews(const capture::Light& light);

/// Unit direction from the light through the centre of texel (x, y) (row 0
/// at the bottom, as GL stores it).
glm::vec3 rsmTexelDirection(const RsmView& view, int resolution, int x, int y);

/// The surface a texel sees, as the RSM holds it.
struct RsmTexelSurface {
  glm::vec3 position_world{0.0f};
  glm::vec3 normal{0.0f};           ///< unit, facing the light
  physics::ScatterVertex vertex{};  ///< its material (physics::scatterVertex)
};

/// The VPL standing for texel (x, y)'s surface (path = eta |x_l - l|, and the
/// texel's patch on the surface for the VPL footprint, the surface's vertex),
/// or nothing when that surface is not lit (outside the spot, black). Its
/// flux: where the vertex's scatter is in the flux (physics::
/// vplFluxHoldsScatter: Lambertian) albedo * I * profile * the texel's solid
/// angle / pi; otherwise (glTF) Phi = I * profile * solid angle, the power it
/// receives, with incoming = the unit direction to the light (a black glTF
/// surface still makes one: its Fresnel lobe reflects).
std::optional<Vpl> rsmTexelVpl(const capture::Light& light, const RsmView& view, int resolution,
                               int x, int y, const RsmTexelSurface& surface,
                               double indexOfRefraction);

/// Per-region media (`media:`): each VPL's flux times the transmittance of
/// its light -> VPL leg through the regions, its path (positionPath.w, eta
/// included) plus the time that leg spends in them.
void attenuateLightLegs(std::vector<Vpl>& vpls, const capture::MediumRegions& regions,
                        const glm::vec3& light_world, double indexOfRefraction);

/// In a medium filling the scene (Medium::present) the RSM VPLs' flux times
/// the light -> VPL leg's transmittance, exp(-sigma_t path / eta) from each
/// VPL's own path (after the edge texels' merges: a merged VPL's light is
/// binned at its nearest member's path, and attenuated by it); without one
/// nothing changes.
void attenuateLightLegs(std::vector<Vpl>& vpls, const capture::Medium& medium,
                        double indexOfRefraction);

}  // namespace tofsim::ir
