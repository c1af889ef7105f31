#include "tofsim/ir/LitPixels.h"

#include "tofsim/ir/SampledPixels.h"
#include "tofsim/physics/TransientPhysics.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::ir {

std::vector<uint8_t> litPixels(const CentreSurfaces& centres, const capture::Light& light,
                               const rays::RayScene& rays, int threads) {
  const std::size_t pixels = centres.positions.size() / 4;
  TOFSIM_CHECK_EQ(centres.normals.size(), pixels * 4);
  const capture::Light::ProfileTerms profile = light.profileTerms();
  std::vector<uint8_t> lit(pixels, 0);
  parallelForBlocks(pixels, 4096, threads, [&](std::size_t first, std::size_t end) {
    for (std::size_t p = first; p < end; ++p) {
      const float* at = &centres.positions[p * 4];
      if (at[3] == 0.0f) continue;
      const glm::vec3 x(at[0], at[1], at[2]);
      const glm::vec3 n(centres.normals[p * 4], centres.normals[p * 4 + 1],
                        centres.normals[p * 4 + 2]);
      const physics::LightArrival arrival =
          physics::lightArrival(x, n, light.position_world, profile.kind, profile.axis,
                                profile.cosOuter, profile.cosInner);
      if (arrival.profile <= 0.0f) continue;
      lit[p] = rays.occluded(x + n * rays.epsilon_m(), light.position_world) ? 0 : 1;
    }
  });
  return lit;
}

std::vector<uint8_t> adaptiveSampledPixels(const CentreSurfaces& centres,
                                           const capture::RenderJob& job,
                                           const rays::RayScene& rays) {
  return sampledPixels(
      centres, capture::imageWidth(job.imager), capture::imageHeight(job.imager),
      litPixels(centres, job.light, rays, job.settings.indirect.trace_threads));
}

}  // namespace tofsim::ir
