// The shared glTF BRDF (shaders/gltf_brdf.glsl): reciprocity on random
// directions and energy (the directional albedo, the integral of f cos over
// the hemisphere of light directions, for a white base colour) by numerical
// quadrature. Note: the BRDF has no Lambertian
// limit (metallic 0, roughness 1 keeps a Fresnel-weighted GGX lobe), so the
// Lambertian path of the renderers is a separate model (render.materials).

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tofsim/physics/GltfBrdf.h"

namespace {

using glm::vec3;

vec3 randomUnitAbove(std::mt19937& rng, const vec3& n) {
  std::normal_distribution<float> g;
  for (;;) {
    vec3 d(g(rng), g(rng), g(rng));
    if (glm::length(d) < 1e-3f) continue;
    d = glm::normalize(d);
    if (glm::dot(d, n) < 0.0f) d = -d;
    if (glm::dot(d, n) > 1e-3f) return d;
  }
}

TEST(GltfBrdf, IsReciprocalOnRandomDirections) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const vec3 n = glm::normalize(vec3(0.2f, 1.0f, -0.3f));
  for (int i = 0; i < 2000; ++i) {
    const vec3 l = randomUnitAbove(rng, n), v = randomUnitAbove(rng, n);
    const vec3 base(u(rng), u(rng), u(rng));
    const float metallic = u(rng), roughness = 0.05f + 0.95f * u(rng);
    const vec3 a = tofsim::physics::gltfBrdf(n, l, v, base, metallic, roughness);
    const vec3 b = tofsim::physics::gltfBrdf(n, v, l, base, metallic, roughness);
    for (int c = 0; c < 3; ++c) {
      ASSERT_TRUE(std::isfinite(a[c]));
      ASSERT_GE(a[c], 0.0f);
      ASSERT_NEAR(a[c], b[c], 1e-5f * std::max(1.0f, std::abs(a[c]))) << "sample " << i;
    }
  }
}

TEST(GltfBrdf, IsZeroBelowTheSurface) {
  const vec3 n(0, 0, 1), up = glm::normalize(vec3(0.3f, 0, 1)), down(0, 0.6f, -0.8f);
  EXPECT_EQ(tofsim::physics::gltfBrdf(n, up, down, vec3(1), 0.5f, 0.5f), vec3(0));
  EXPECT_EQ(tofsim::physics::gltfBrdf(n, down, up, vec3(1), 0.5f, 0.5f), vec3(0));
}

// Integral of f(l, v) cos(theta_l) over the hemisphere of l, in double, by the
// midpoint rule in (cos theta, phi): dw = d(cos theta) d(phi). The rule is
// refined near the normal (where the lobe of a smooth surface sits at normal
// incidence) by a change of variable cos theta = 1 - s^2.
double directionalAlbedo(const vec3& v, float metallic, float roughness) {
  const vec3 n(0, 0, 1);
  constexpr int kS = 1200, kPhi = 720;
  const double pi = 3.14159265358979323846;
  double sum = 0.0;
  for (int i = 0; i < kS; ++i) {
    const double s = (i + 0.5) / kS;  // cos theta = 1 - s^2, d(cos) = 2 s ds
    const double cosT = 1.0 - s * s;
    const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
    for (int j = 0; j < kPhi; ++j) {
      const double phi = 2.0 * pi * (j + 0.5) / kPhi;
      const vec3 l(static_cast<float>(sinT * std::cos(phi)),
                   static_cast<float>(sinT * std::sin(phi)), static_cast<float>(cosT));
      const vec3 f = tofsim::physics::gltfBrdf(n, l, v, vec3(1.0f), metallic, roughness);
      sum += f.g * cosT * (2.0 * s / kS) * (2.0 * pi / kPhi);
    }
  }
  return sum;
}

// White base colour: the metal conserves energy at every view (its single
// scattering loses some: 0.31 at roughness 1, normal view), and so does
// every mix up to a 30-degree view. The pinned dielectric mix does NOT at
// grazing views: its diffuse weight 1 - F(0.04, v.h) is taken per light
// direction, and at a grazing view the specular half vectors have small v.h,
// so the Fresnel-weighted lobe and the barely darkened diffuse term add up
// to more than 1 (measured here, converged: 1.0010 at 45 deg, 1.025 at 60
// deg, 1.221 at 80 deg for roughness 0.3). That is a property of the BRDF
// issue 16 pins (Khronos' fresnel_mix), kept, and bounded here so a change
// shows.
TEST(GltfBrdf, ReflectsAtMostTheIncidentEnergyForAWhiteBaseColour) {
  for (const float roughness : {0.3f, 0.6f, 1.0f}) {
    for (const float metallic : {0.0f, 0.5f, 1.0f}) {
      for (const float thetaDeg : {0.0f, 30.0f, 60.0f, 80.0f}) {
        const float t = glm::radians(thetaDeg);
        const vec3 v(std::sin(t), 0.0f, std::cos(t));
        const double albedo = directionalAlbedo(v, metallic, roughness);
        const bool conserving = metallic == 1.0f || thetaDeg <= 30.0f;
        EXPECT_LE(albedo, conserving ? 1.0 : 1.23) << "roughness " << roughness << " metallic "
                                                   << metallic << " view " << thetaDeg << " deg";
        EXPECT_GT(albedo, 0.3) << "roughness " << roughness << " metallic " << metallic;
      }
    }
  }
}

}  // namespace
