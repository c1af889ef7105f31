#pragma once
// Continuing a light path at a scattering vertex (ScatterVertex.h), for IR's
// later-bounce VPLs (ir::traceBounce): the direction drawn at a VPL and the
// flux its child carries. The material models are told apart here, not in
// the VPL makers.

#include <glm/glm.hpp>

#include "tofsim/physics/GltfSampling.h"
#include "tofsim/physics/HemisphereSampling.h"
#include "tofsim/physics/ScatterVertex.h"

namespace tofsim::physics {

/// The continuation of the light path at a VPL of vertex v (unit normal n,
/// its light come from unit `incoming`): its direction and the factor its
/// power gains there. Cosine-weighted about n where the VPL's flux holds its
/// scatter (Lambertian: its albedo is in its flux already, weight 1; two
/// numbers of rng); otherwise the BRDF sampled as the reference does
/// (sampleGltfBounce: the mixture of the cosine lobe and GGX visible normals
/// about `incoming`), gaining f cos / pdf with f clamped at brdfClampPerSr as
/// the gather clamps it (three numbers).
template <class Rng>
GltfBounce sampleVplContinuation(const ScatterVertex& v, const glm::vec3& n,
                                 const glm::vec3& incoming, float brdfClampPerSr, Rng& rng) {
  if (vplFluxHoldsScatter(v)) {
    const float u1 = rng.nextFloat();
    const float u2 = rng.nextFloat();
    return {cosineSampleHemisphere(n, u1, u2), glm::vec3(1.0f)};
  }
  const float uLobe = rng.nextFloat();
  const float u1 = rng.nextFloat();
  const float u2 = rng.nextFloat();
  return sampleGltfBounce(n, incoming, glm::vec3(v.color), v.color.w, v.roughness, uLobe, u1, u2,
                          brdfClampPerSr);
}

/// The flux of a later bounce's VPL at vertex v that receives `share` of its
/// parent's flux through a continuation of `weight`: its albedo times the
/// share where its flux holds its scatter (Lambertian), else the power
/// share * weight (W).
inline glm::vec3 bounceVplFlux(const ScatterVertex& v, const glm::vec3& share,
                               const glm::vec3& weight) {
  return vplFluxHoldsScatter(v) ? glm::vec3(v.color) * share : share * weight;
}

}  // namespace tofsim::physics
