// CpuIsm::cullHidden, the gather's ISM test eight lanes at a time, against
// CpuIsm::visible lane by lane: the same verdicts (the same float steps), on
// VPLs of the corner scene with normals of every sign, directions into and
// out of the maps' occluders, distances on both sides of the bias.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "CpuIsm.h"
#include "support/AnalyticScenes.h"

namespace tofsim::cpu {
namespace {

std::vector<ir::Vpl> vplsAround(std::mt19937& rng, std::size_t count) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), at(0.05f, 0.95f);
  std::vector<ir::Vpl> vpls(count);
  for (ir::Vpl& v : vpls) {
    glm::vec3 n(u(rng), u(rng), u(rng));
    n = glm::normalize(n + glm::vec3(0.0f, 0.0f, 1e-3f));
    // Some normals exactly along an axis (basisAround's sign branch).
    if (&v - vpls.data() < 4) n = glm::vec3(0.0f, 0.0f, (&v - vpls.data()) % 2 ? 1.0f : -1.0f);
    v.positionPath = glm::vec4(at(rng), at(rng) * 0.5f, at(rng), 1.0f);
    v.normal = glm::vec4(n, 0.0f);
  }
  return vpls;
}

TEST(IsmCullTest, EightLanesAtATimeGiveVisiblesVerdicts) {
  const scene::Scene scene = test::makeCorner(glm::vec3(0.5f), glm::vec3(0.5f));
  std::mt19937 rng(7);
  const std::vector<ir::Vpl> vpls = vplsAround(rng, 300);  // a block and a part
  capture::IndirectSettings settings;
  settings.ism_resolution = 32;
  settings.points_per_vpl = 3000;
  CpuIsm ism(scene, vpls, settings, 11);
  ism.allocate(vpls.size());
  ism.build(0, vpls.size(), 2);
  const float sceneScale = 1.0f;
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), dist(0.0f, 1.5f);
  std::size_t hidden = 0, shown = 0;
  // Receivers facing every way: the tolerance's slope from facing the VPL to
  // grazing; and a medium point (normal 0, receiver cosine 1: offset 1).
  const std::array<glm::vec3, 4> receiverNormals{glm::vec3(0, 0, 1),
                                                 glm::normalize(glm::vec3(1, -2, 0.3f)),
                                                 glm::vec3(0, -1, 0), glm::vec3(0.0f)};
  for (std::size_t first = 0; first < vpls.size(); first += kVplBlock) {
    const std::size_t n = std::min(kVplBlock, vpls.size() - first);
    for (int round = 0; round < 20; ++round) {
      VplTerms terms;
      for (std::size_t i = 0; i < n; ++i) {
        glm::vec3 d = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0, 0, 1e-3f));
        if (glm::dot(d, glm::vec3(vpls[first + i].normal)) < 0.0f) d = -d;  // the lit side
        terms.dx[i] = d.x, terms.dy[i] = d.y, terms.dz[i] = d.z, terms.dist[i] = dist(rng);
        terms.bin[i] = static_cast<int32_t>(i % 3 == 0 ? kNoLight : 5 + i);
      }
      VplTerms culled = terms;
      const glm::vec3 receiverNormal = receiverNormals[(first / kVplBlock + round) % 4];
      const float offset = receiverNormal == glm::vec3(0.0f) ? 1.0f : 0.0f;
      ism.cullHidden(first, n, sceneScale, receiverNormal, offset, culled);
      for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 d(terms.dx[i], terms.dy[i], terms.dz[i]);
        const bool visible =
            ism.visible(first + i, d, terms.dist[i], receiverNormal, offset, sceneScale);
        const int32_t expected = visible ? terms.bin[i] : kNoLight;
        ASSERT_EQ(culled.bin[i], expected) << "vpl " << first + i << " lane " << i;
        (visible ? shown : hidden) += terms.bin[i] != kNoLight;
      }
    }
  }
  // Both verdicts occur: the test compares something.
  EXPECT_GT(hidden, 300u);
  EXPECT_GT(shown, 500u);
}

}  // namespace
}  // namespace tofsim::cpu
