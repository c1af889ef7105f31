// The CPU gather's near field: vplTerms gives a pair within a VPL's near
// field the patch's integral, its patches above the pixel's horizon eight
// lanes at a time and the clipped ones one by one. Both against the shared
// scalar recipe (physics::vplGeometryTerm), bit for bit, on a crease: VPLs
// on a wall, pixels on the floor below them, some patches across the
// floor's plane.

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "GatherKernel.h"
#include "tofsim/physics/VplNearField.h"

namespace tofsim::cpu {
namespace {

TEST(NearFieldLanesTest, EveryNearLaneGetsThePatchIntegralBitForBit) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  // Wall x = 0 facing +x, 2 cm patches; the floor y = 0 facing +y.
  std::vector<ir::Vpl> vpls(300);
  for (ir::Vpl& v : vpls) {
    const float y = 0.03f * u(rng) - 0.005f;  // some patches reach below the floor
    v.positionPath = glm::vec4(0.0f, y, 0.2f * u(rng), 1.0f);
    v.normal = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    v.flux = glm::vec4(0.5f, 0.25f, 0.125f, 0.0f);
    v.patchU = glm::vec4(0.0f, 0.0f, 0.02f, 0.0f);
    v.patchV = glm::vec4(0.0f, 0.02f, 0.0f, 0.0f);
  }
  const VplArrays arrays(vpls);
  GatherConstants c;
  c.start_m = 0.0f, c.binWidth_m = 0.003f, c.indexOfRefraction = 1.0f, c.bins = 4096;
  std::size_t clipped = 0, above = 0;
  for (int pixel = 0; pixel < 40; ++pixel) {
    PixelSurface s;
    s.x = glm::vec3(0.1f * u(rng) + 0.002f, 0.0f, 0.2f * u(rng));
    s.n = glm::vec3(0.0f, 1.0f, 0.0f);
    s.brdf = glm::vec3(0.3f, 0.2f, 0.1f);
    s.camera = glm::vec3(0.5f, 1.0f, 0.1f);
    for (std::size_t first = 0; first < vpls.size(); first += kVplBlock) {
      const std::size_t n = std::min(kVplBlock, vpls.size() - first);
      VplTerms terms;
      vplTerms(s, arrays, first, n, c, terms);
      for (std::size_t i = 0; i < n; ++i) {
        if (terms.bin[i] == kNoLight || !terms.nearField[i]) continue;
        const std::size_t k = first + i;
        const glm::vec3 d(terms.dx[i], terms.dy[i], terms.dz[i]);
        const glm::vec3 vplX(arrays.px[k], arrays.py[k], arrays.pz[k]);
        const glm::vec3 patchU(arrays.ux[k], arrays.uy[k], arrays.uz[k]);
        const glm::vec3 patchV(arrays.vx[k], arrays.vy[k], arrays.vz[k]);
        const glm::vec3 toX = s.x - vplX;
        const float tx = toX.x, ty = toX.y, tz = toX.z;
        const float g = physics::vplGeometryTerm(
            arrays.nx[k] * d.x + arrays.ny[k] * d.y + arrays.nz[k] * d.z,
            -(s.n.x * d.x + s.n.y * d.y + s.n.z * d.z), tx * tx + ty * ty + tz * tz, 0.0f, s.x,
            s.n, vplX, patchU, patchV);
        const float expected = s.brdf.r * arrays.fr[k] * g;
        ASSERT_EQ(std::memcmp(&terms.r[i], &expected, sizeof expected), 0)
            << "pixel " << pixel << " vpl " << k << ": " << terms.r[i] << " vs " << expected;
        const physics::PatchCorners q = physics::patchCornersFrom(s.x, vplX, patchU, patchV);
        (physics::patchAboveHorizon(q, s.n) ? above : clipped) += 1;
      }
    }
  }
  // Both paths ran: the test compares something on each.
  EXPECT_GT(above, 100u);
  EXPECT_GT(clipped, 20u);
}

}  // namespace
}  // namespace tofsim::cpu
