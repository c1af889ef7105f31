// A VPL's light near its own patch (shaders/vpl_near_field.glsl through
// tofsim/physics/VplNearField.h): the patch's projected solid angle against
// the closed form of a square seen head-on and against a fine quadrature of
// cos cos / d^2 over patches that cross the receiver's horizon (a crease);
// the switch from the point VPL continuous to the midpoint rule's error; and
// the term bounded where the point VPL's is not.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "tofsim/physics/VplNearField.h"

namespace tofsim::physics {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Form factor from a point to a parallel a x b rectangle at height h with a
// corner straight above it (Siegel and Howell, configuration B-3).
double cornerRectangleFormFactor(double a, double b, double h) {
  const double x = a / h, y = b / h;
  const double sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
  return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * kPi);
}

// The integral over the patch of cos_l+ cos_x+ / d^2 dA by the midpoint rule
// on n x n cells, in double: the projected solid angle of the part above x's
// horizon (cos_l: the patch emits to the side of `patchNormal`).
double quadrature(const glm::dvec3& x, const glm::dvec3& nx, const glm::dvec3& centre,
                  const glm::dvec3& u, const glm::dvec3& v, const glm::dvec3& patchNormal, int n) {
  const double cell = glm::length(glm::cross(u, v)) / (static_cast<double>(n) * n);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const glm::dvec3 p = centre + u * ((i + 0.5) / n - 0.5) + v * ((j + 0.5) / n - 0.5);
      const glm::dvec3 d = x - p;
      const double d2 = glm::dot(d, d);
      const double cosL = glm::dot(patchNormal, d) / std::sqrt(d2);
      const double cosX = -glm::dot(nx, d) / std::sqrt(d2);
      if (cosL > 0.0 && cosX > 0.0) sum += cosL * cosX / d2 * cell;
    }
  }
  return sum;
}

// The edges' angles: Cephes' atanf against atan2 in double, over every
// octant and magnitudes from 1e-30 to 1e30 (sine >= 0, as |a x b| is).
TEST(VplNearFieldTest, TheEdgeAngleIsAtan2) {
  double worst = 0.0;
  for (int k = 0; k <= 20000; ++k) {
    const double theta = kPi * k / 20000.0;
    for (double scale : {1e-30, 1e-6, 1.0, 3.7e4, 1e30}) {
      const auto sine = static_cast<float>(scale * std::sin(theta));
      const auto cosine = static_cast<float>(scale * std::cos(theta));
      if (sine < 0.0f || !(sine > 0.0f || cosine != 0.0f)) continue;
      const double exact = std::atan2(static_cast<double>(sine), static_cast<double>(cosine));
      worst = std::max(worst, std::abs(static_cast<double>(edgeAngle(sine, cosine)) - exact));
    }
  }
  std::printf("edgeAngle: worst error %.3g rad\n", worst);
  EXPECT_LT(worst, 4e-7);
  EXPECT_EQ(edgeAngle(1.0f, 0.0f), static_cast<float>(kPi / 2));
  EXPECT_NEAR(edgeAngle(1e-20f, -1.0f), kPi, 1e-6);
}

TEST(VplNearFieldTest, ASquareSeenHeadOnHasTheClosedFormProjectedSolidAngle) {
  const float side = 0.02f;
  for (const float h : {0.002f, 0.02f, 0.2f}) {
    const vec3 x(0.3f, -0.1f, 0.5f), n(0.0f, 0.0f, 1.0f);
    const float omega = patchProjectedSolidAngle(x, n, x + vec3(0.0f, 0.0f, h),
                                                 vec3(side, 0.0f, 0.0f), vec3(0.0f, side, 0.0f));
    const double closed = 4.0 * kPi * cornerRectangleFormFactor(side / 2.0, side / 2.0, h);
    EXPECT_NEAR(omega, closed, 2e-5 * closed) << "height " << h;
  }
}

TEST(VplNearFieldTest, PatchesAcrossTheHorizonMatchAQuadrature) {
  // A wall patch standing on x's floor (a crease) and random tilted patches
  // near x, some of them partly below x's horizon: the clip is what is tested.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int clipped = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const glm::dvec3 x(0.0), nx(0.0, 0.0, 1.0);
    glm::dvec3 centre, u, v;
    if (trial == 0) {  // the crease: wall x = 0.005 m, from z = 0 up
      centre = {0.005, 0.0, 0.01}, u = {0.0, 0.02, 0.0}, v = {0.0, 0.0, 0.02};
    } else {
      centre = glm::dvec3(unit(rng), unit(rng), 0.5 * unit(rng) + 0.1) * 0.03;
      u = glm::dvec3(unit(rng), unit(rng), unit(rng)) * 0.02;
      v = glm::dvec3(unit(rng), unit(rng), unit(rng)) * 0.02;
    }
    glm::dvec3 patchNormal = glm::normalize(glm::cross(u, v));
    if (glm::dot(patchNormal, x - centre) < 0.0) patchNormal = -patchNormal;  // x in front
    bool across = false;
    for (const double su : {-0.5, 0.5}) {
      for (const double sv : {-0.5, 0.5}) across |= (centre + su * u + sv * v).z < 0.0;
    }
    clipped += across;
    const double expected = quadrature(x, nx, centre, u, v, patchNormal, 1500);
    const float omega = patchProjectedSolidAngle(vec3(x), vec3(nx), vec3(centre), vec3(u), vec3(v));
    EXPECT_NEAR(omega, expected, 1e-3 * expected + 1e-6) << "trial " << trial;
  }
  EXPECT_GT(clipped, 5);  // the clip was exercised
}

TEST(VplNearFieldTest, ThePointTermTakesOverContinuouslyAtTheNearFieldsEdge) {
  // A 1 cm patch facing x head-on, at distances either side of the switch.
  const vec3 x(0.0f), n(0.0f, 0.0f, 1.0f), u(0.01f, 0.0f, 0.0f), v(0.0f, 0.01f, 0.0f);
  const float width = 0.01f;
  for (const float widths : {NEAR_FIELD_WIDTHS * 0.999f, NEAR_FIELD_WIDTHS * 1.001f}) {
    const float h = widths * width;
    const vec3 vpl(0.0f, 0.0f, h);
    const float g = vplGeometryTerm(1.0f, 1.0f, h * h, 0.0f, x, n, vpl, u, v);
    EXPECT_EQ(vplInNearField(h * h, vplNearFieldLimit(u, v)), widths < NEAR_FIELD_WIDTHS);
    // Both sides within the midpoint rule's error, A / (3 d^2) relative, of 1 / h^2.
    EXPECT_NEAR(g * h * h, 1.0f, 1.0f / (3.0f * widths * widths) + 1e-5f) << widths;
    if (widths < NEAR_FIELD_WIDTHS) {
      EXPECT_LT(g * h * h, 1.0f) << "the patch's integral is below its midpoint rule";
    } else {
      EXPECT_EQ(g, 1.0f / (h * h)) << "outside: the point VPL's term";
    }
  }
}

TEST(VplNearFieldTest, TheTermIsBoundedAtTheCreaseWhereThePointVplsIsNot) {
  // A wall patch (the plane x = 0, facing -x) whose centre lies h above the
  // floor's crease, x on the floor h in front of the wall: the point VPL
  // gives cos cos / d^2 = 0.25 / h^2, without bound as h -> 0 (the crease's
  // spikes); the patch's integral (its part above the floor) stays below
  // pi / A, unclamped whatever the clamp.
  const vec3 n(0.0f, 0.0f, 1.0f);
  const vec3 u(0.0f, 0.01f, 0.0f), v(0.0f, 0.0f, 0.01f);
  const float area = 1e-4f;
  float last = 0.0f;
  for (const float h : {1e-3f, 1e-5f, 1e-7f}) {
    const vec3 centre(0.0f, 0.0f, h), x(-h, 0.0f, 0.0f);
    const vec3 toX = x - centre;
    const float dist2 = glm::dot(toX, toX);
    const float point = geometryTerm(0.70710678f, 0.70710678f, dist2, 0.0f);
    EXPECT_NEAR(point, 0.25f / (h * h), 1e-3f * point) << h;
    const float g = vplGeometryTerm(0.70710678f, 0.70710678f, dist2, 100.0f, x, n, centre, u, v);
    EXPECT_GT(g * area, 0.1f) << h;
    EXPECT_LE(g * area, static_cast<float>(kPi)) << h;
    last = g;
  }
  // The limit: from the foot of the wall, 1e-7 m from it, the patch's upper
  // half fills the quarter of the sky beyond the wall: half the hemisphere's
  // projected solid angle pi, as an infinite wall would.
  EXPECT_NEAR(last * area, 0.5f * static_cast<float>(kPi), 1e-4f);
}

TEST(VplNearFieldTest, APatchAboveTheHorizonGivesItsExactIntegralUnclamped) {
  // The wall patch lifted wholly above the floor (its foot 1 mm up), x on
  // the floor 2 mm in front: the patch's integral (the point term at its
  // centre is 20 % under it: the patch's foot, nearest x, gives most), and no clamp.
  const vec3 n(0.0f, 0.0f, 1.0f), x(-0.002f, 0.0f, 0.0f);
  const vec3 u(0.0f, 0.01f, 0.0f), v(0.0f, 0.0f, 0.01f), centre(0.0f, 0.0f, 0.006f);
  // (the patch spans z = 1 .. 11 mm: wholly above x's floor)
  const double expected =
      quadrature(glm::dvec3(x), glm::dvec3(n), glm::dvec3(centre), glm::dvec3(u), glm::dvec3(v),
                 glm::dvec3(-1.0, 0.0, 0.0), 2000) /
      1e-4;
  const vec3 toX = x - centre;
  const float dist = glm::length(toX);
  const float cosVpl = 0.002f / dist, cosX = 0.006f / dist;
  const float g = vplGeometryTerm(cosVpl, cosX, dist * dist, 100.0f, x, n, centre, u, v);
  EXPECT_NEAR(g, expected, 1e-3 * expected);
  EXPECT_LT(geometryTerm(cosVpl, cosX, dist * dist, 0.0f), 0.85f * g);  // the midpoint's shortfall
}

TEST(VplNearFieldTest, APointVplHasNoNearField) {
  // A later bounce's VPL (patch steps 0) keeps the point term, clamp included.
  const vec3 zero(0.0f);
  EXPECT_FALSE(vplInNearField(1e-8f, vplNearFieldLimit(zero, zero)));
  EXPECT_EQ(vplGeometryTerm(1.0f, 1.0f, 1e-4f, 100.0f, vec3(0.0f), vec3(0.0f, 0.0f, 1.0f),
                            vec3(0.0f, 0.0f, 0.01f), zero, zero),
            100.0f);
}

// A medium point's near field (vplMediumGeometryTerm): the patch's solid
// angle, by Van Oosterom and Strackee's formula, against closed forms: an
// octant's triangle is pi / 2 from the origin; a square of side a seen on its
// axis at height h is 4 asin(a^2 / (a^2 + 4 h^2)), 2 pi on its plane inside
// it and 0 on it outside it.
TEST(VplNearFieldTest, APatchsSolidAngleMatchesClosedForms) {
  EXPECT_NEAR(triangleSolidAngle(glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)),
              1.5707963, 1e-6);
  const float a = 0.3f;
  const glm::vec3 u(a, 0.0f, 0.0f), v(0.0f, a, 0.0f), centre(0.5f, -0.2f, 1.0f);
  for (const float h : {1e-4f, 0.01f, 0.1f, 1.0f, 10.0f}) {
    const double expected = 4.0 * std::asin(double(a) * a / (double(a) * a + 4.0 * h * h));
    EXPECT_NEAR(patchSolidAngle(centre + glm::vec3(0, 0, h), centre, u, v), expected,
                2e-6 + 1e-5 * expected)
        << "h " << h;
    // From below: the same (the lit side is the caller's test).
    EXPECT_NEAR(patchSolidAngle(centre - glm::vec3(0, 0, h), centre, u, v), expected,
                2e-6 + 1e-5 * expected);
  }
  EXPECT_NEAR(patchSolidAngle(centre + glm::vec3(0.05f, 0.1f, 0.0f), centre, u, v), 6.2831853,
              1e-5);
  EXPECT_NEAR(patchSolidAngle(centre + glm::vec3(1.0f, 0.0f, 0.0f), centre, u, v), 0.0, 1e-6);
  // Beyond the near field: the point VPL's cos / d^2, clamped.
  const float far = 10.0f * a;
  EXPECT_EQ(
      vplMediumGeometryTerm(1.0f, far * far, 0.0f, centre + glm::vec3(0, 0, far), centre, u, v),
      1.0f / (far * far));
  EXPECT_EQ(vplMediumGeometryTerm(1.0f, 1e-4f, 50.0f, centre + glm::vec3(0, 0, far), glm::vec3(0),
                                  glm::vec3(0), glm::vec3(0)),
            50.0f);
}

}  // namespace
}  // namespace tofsim::physics
