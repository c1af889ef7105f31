// Later bounces from glossy VPLs (render.materials: gltf, ir::traceBounce
// with BounceMaterials::gltf): a child receives its share of the parent's
// power times the cosine sample's weight pi f(incoming, w), so in a closed
// box, where every ray hits, the children's total is the parent's power times
// its directional albedo for the direction its light came from (a quadrature
// of f cos here, the BRDF in double: support/ExpectedGltfBrdf.h); each child
// comes in from its parent and carries the material it landed on; the clamp
// only takes light away.

#include <gtest/gtest.h>

#include <cmath>

#include "support/AnalyticScenes.h"
#include "support/ExpectedGltfBrdf.h"
#include "tofsim/ir/BounceVpls.h"
#include "tofsim/rays/RayScene.h"

namespace tofsim::ir {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Directional albedo integral f(l, v) cos dv over the hemisphere of n = +y,
// midpoint rule in (cos theta, phi).
glm::dvec3 directionalAlbedo(const glm::dvec3& l, const glm::dvec3& base, double metallic,
                             double roughness) {
  const int nu = 2000, nphi = 400;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < nu; ++i) {
    const double c = (i + 0.5) / nu, s = std::sqrt(1.0 - c * c);
    for (int j = 0; j < nphi; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / nphi;
      const glm::dvec3 v(s * std::cos(phi), c, s * std::sin(phi));
      sum += test::expectedGltfBrdf({0, 1, 0}, l, v, base, metallic, roughness) * c;
    }
  }
  return sum * (2.0 * kPi / (double(nu) * nphi));
}

TEST(GlossyBounceVplsTest, ChildrenCarryTheParentsPowerTimesItsDirectionalAlbedo) {
  scene::Scene box = test::makeClosedBox(2.0f, glm::vec3(0.6f, 0.5f, 0.4f));
  for (scene::Material& m : box.materials) m.metallic = 0.3f, m.roughness = 0.5f;
  const rays::RayScene scene(box, 1);
  const glm::vec3 incoming = glm::normalize(glm::vec3(0.5f, 1.0f, 0.2f));
  Vpl parent{glm::vec4(0.2f, -1.0f, 0.1f, 2.0f), glm::vec4(0, 1, 0, 0),
             glm::vec4(1.0f, 0.5f, 0.25f, 0.0f)};  // the power it received, W
  parent.incoming = glm::vec4(incoming, 0.0f);
  // A metal of roughness 0.4.
  parent.vertex = physics::scatterVertex(physics::VERTEX_GLTF, {0.9f, 0.7f, 0.5f}, 1.0f, 0.4f);
  const std::size_t count = 20000;
  const BounceMaterials gltf{physics::VERTEX_GLTF, 0.0f};
  const std::vector<Vpl> children = traceBounce(scene, {parent}, count, 2, 7, 1.0, {}, gltf);
  // Closed: no ray escapes; the GGX lobe's directions below the surface end
  // their paths (the light the surface does not reflect), a few per cent here.
  ASSERT_LE(children.size(), count);
  ASSERT_GT(children.size(), count * 9 / 10);
  glm::dvec3 sum(0.0);
  for (const Vpl& c : children) {
    sum += glm::dvec3(glm::vec3(c.flux));
    const glm::vec3 toParent = glm::normalize(glm::vec3(parent.positionPath - c.positionPath));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(c.incoming[i], toParent[i], 1e-4f);
    EXPECT_EQ(c.incoming.w, 0.0f);
    EXPECT_EQ(c.vertex.color, glm::vec4(0.6f, 0.5f, 0.4f, 0.3f));
    EXPECT_EQ(c.vertex.roughness, 0.5f);
    EXPECT_EQ(c.vertex.model, physics::VERTEX_GLTF);
  }
  const glm::dvec3 albedo =
      directionalAlbedo(glm::dvec3(incoming), glm::dvec3(0.9, 0.7, 0.5), 1.0, 0.4);
  // Monte Carlo over 20000 BRDF samples (the mixture of the cosine lobe and
  // GGX visible normals, weight f cos / pdf): well under 1 % standard error.
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(sum[c] / parent.flux[c], albedo[c], 0.04 * albedo[c]) << "channel " << c;
  }
  // The same directions (same seed) with the clamp: no child gains light.
  const std::vector<Vpl> clamped = traceBounce(scene, {parent}, count, 2, 7, 1.0, {},
                                               BounceMaterials{physics::VERTEX_GLTF, 0.5f});
  ASSERT_EQ(clamped.size(), children.size());
  double removed = 0.0;
  for (std::size_t k = 0; k < clamped.size(); ++k) {
    EXPECT_EQ(clamped[k].positionPath, children[k].positionPath);
    for (int c = 0; c < 3; ++c) {
      EXPECT_LE(clamped[k].flux[c], children[k].flux[c]);
      removed += children[k].flux[c] - clamped[k].flux[c];
    }
  }
  EXPECT_GT(removed, 0.0);
}

}  // namespace
}  // namespace tofsim::ir
