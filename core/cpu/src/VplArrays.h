#pragma once
// VPLs as structure-of-arrays, so the gather's inner loop reads each quantity
// of consecutive VPLs from consecutive floats (SIMD loads, no gathers). The
// glossy VPL's direction and material (render.materials: gltf) are held only
// when asked for.

#include <cstddef>
#include <vector>

#include "tofsim/ir/IrBackend.h"
#include "tofsim/physics/VplNearField.h"

namespace tofsim::cpu {

struct VplArrays {
  std::vector<float> px, py, pz, path;  ///< position (world, m), optical path light -> VPL (m)
  std::vector<float> nx, ny, nz;        ///< unit normal, lit side
  std::vector<float> fr, fg, fb;        ///< ir::Vpl::flux: albedo * Phi / pi, W/sr (gltf: Phi, W)
  std::vector<float> ux, uy, uz, uw;    ///< patch step along the RSM's right axis, w: light leg
  std::vector<float> vx, vy, vz, vw;    ///< along its up axis (ir::Vpl::patchU / patchV)
  std::vector<float> nearLimit;         ///< physics::vplNearFieldLimit of the patch, m^4
  /// glossy only (empty otherwise): ir::Vpl::incoming (unit direction the
  /// light came from) and the material (base colour, metallic, roughness).
  std::vector<float> ix, iy, iz, br, bg, bb, metallic, roughness;
  std::size_t count = 0;
  bool glossy = false;

  explicit VplArrays(const std::vector<ir::Vpl>& vpls = {}, bool withMaterials = false)
      : count(vpls.size()), glossy(withMaterials) {
    for (std::vector<float>* a : {&px, &py, &pz, &path, &nx, &ny, &nz, &fr, &fg, &fb, &ux, &uy, &uz,
                                  &uw, &vx, &vy, &vz, &vw, &nearLimit}) {
      a->resize(count);
    }
    for (std::size_t k = 0; k < count; ++k) {
      const ir::Vpl& v = vpls[k];
      px[k] = v.positionPath.x, py[k] = v.positionPath.y, pz[k] = v.positionPath.z;
      path[k] = v.positionPath.w;
      nx[k] = v.normal.x, ny[k] = v.normal.y, nz[k] = v.normal.z;
      fr[k] = v.flux.r, fg[k] = v.flux.g, fb[k] = v.flux.b;
      ux[k] = v.patchU.x, uy[k] = v.patchU.y, uz[k] = v.patchU.z, uw[k] = v.patchU.w;
      vx[k] = v.patchV.x, vy[k] = v.patchV.y, vz[k] = v.patchV.z, vw[k] = v.patchV.w;
      nearLimit[k] = physics::vplNearFieldLimit(glm::vec3(v.patchU), glm::vec3(v.patchV));
    }
    if (!glossy) return;
    for (std::vector<float>* a : {&ix, &iy, &iz, &br, &bg, &bb, &metallic, &roughness}) {
      a->resize(count);
    }
    for (std::size_t k = 0; k < count; ++k) {
      const ir::Vpl& v = vpls[k];
      ix[k] = v.incoming.x, iy[k] = v.incoming.y, iz[k] = v.incoming.z;
      metallic[k] = v.incoming.w;
      br[k] = v.material.r, bg[k] = v.material.g, bb[k] = v.material.b;
      roughness[k] = v.material.w;
    }
  }
  std::size_t bytes() const { return count * (glossy ? 27 : 19) * sizeof(float); }
};

}  // namespace tofsim::cpu
