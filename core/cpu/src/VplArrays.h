#pragma once
// VPLs as structure-of-arrays, so the gather's inner loop reads each quantity
// of consecutive VPLs from consecutive floats (SIMD loads, no gathers): one
// array per float of ir::Vpl that the gathers read. The direction a VPL's
// light came from and its vertex (ir::Vpl::incoming, ::vertex) are held only
// where some VPL's scatter is not in its flux (physics::vplFluxHoldsScatter:
// all of them are for Lambertian VPLs), which `scattering` says.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tofsim/ir/IrBackend.h"
#include "tofsim/ir/MediumVpl.h"
#include "tofsim/physics/ScatterVertex.h"
#include "tofsim/physics/VplNearField.h"

namespace tofsim::cpu {

struct VplArrays {
  std::vector<float> px, py, pz, path;  ///< position (world, m), optical path light -> VPL (m)
  std::vector<float> nx, ny, nz;        ///< unit normal, lit side
  std::vector<float> fr, fg, fb;        ///< ir::Vpl::flux (W/sr, or W where `scattering`)
  std::vector<float> ux, uy, uz, uw;    ///< patch step along the RSM's right axis, w: light leg
  std::vector<float> vx, vy, vz, vw;    ///< along its up axis (ir::Vpl::patchU / patchV)
  std::vector<float> nearLimit;         ///< physics::vplNearFieldLimit of the patch, m^4
  /// physics::vplEmitterCosine with no branch per lane: the emitter cosine
  /// toward d is emitterOffset + n . d (1 + 0 at a medium VPL, whose normal
  /// is zero; 0 + n . d, the same float, at a surface VPL).
  std::vector<float> emitterOffset;
  /// Only where `scattering` (empty otherwise): ir::Vpl::incoming and ::vertex.
  std::vector<float> ix, iy, iz;
  std::vector<physics::ScatterVertex> vertex;
  /// Each VPL's response class (ir::Vpl::flux.w, ir/VplClasses.h); empty
  /// where every VPL's is 0 (instant).
  std::vector<uint32_t> responseClass;
  std::size_t count = 0;
  bool scattering = false;  ///< some VPL's scatter is not in its flux: vplScatter it
  /// Some VPL is a medium VPL (ir::isMediumVpl): it has no hemisphere map,
  /// so it is tested exactly whatever the visibility (CpuBackend).
  bool anyMedium = false;

  explicit VplArrays(const std::vector<ir::Vpl>& vpls = {}) : count(vpls.size()) {
    for (std::vector<float>* a : {&px, &py, &pz, &path, &nx, &ny, &nz, &fr, &fg, &fb, &ux, &uy, &uz,
                                  &uw, &vx, &vy, &vz, &vw, &nearLimit, &emitterOffset}) {
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
      emitterOffset[k] = ir::isMediumVpl(v) ? 1.0f : 0.0f;
      anyMedium = anyMedium || ir::isMediumVpl(v);
      scattering = scattering || !physics::vplFluxHoldsScatter(v.vertex);
      if (v.flux.w != 0.0f && responseClass.empty()) responseClass.assign(count, 0u);
    }
    for (std::size_t k = 0; k < count && !responseClass.empty(); ++k) {
      responseClass[k] = static_cast<uint32_t>(vpls[k].flux.w);
    }
    if (!scattering) return;
    for (std::vector<float>* a : {&ix, &iy, &iz}) a->resize(count);
    vertex.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
      const ir::Vpl& v = vpls[k];
      ix[k] = v.incoming.x, iy[k] = v.incoming.y, iz[k] = v.incoming.z;
      vertex[k] = v.vertex;
    }
  }

  /// What VPL k sends toward unit d besides its flux (physics::vplScatter).
  glm::vec3 scatterToward(std::size_t k, const glm::vec3& d, float clampPerSr) const {
    if (!scattering) return glm::vec3(1.0f);
    return physics::vplScatter(vertex[k], glm::vec3(nx[k], ny[k], nz[k]),
                               glm::vec3(ix[k], iy[k], iz[k]), d, clampPerSr);
  }

  std::size_t bytes() const {
    return count * (20 * sizeof(float) + (responseClass.empty() ? 0 : sizeof(uint32_t)) +
                    (scattering ? 3 * sizeof(float) + sizeof(physics::ScatterVertex) : 0));
  }
};

}  // namespace tofsim::cpu
