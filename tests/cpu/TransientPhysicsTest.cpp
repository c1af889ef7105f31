// The shared physics header (shaders/transient_physics.glsl) compiled as C++,
// against values worked out by hand. The GL side compiles the same file in
// every gather shader, so the GL tests cover its GLSL face.
#include <gtest/gtest.h>

#include "tofsim/physics/TransientPhysics.h"

namespace tofsim::physics {
namespace {

TEST(TransientPhysics, SpotFalloffIsOneInsideZeroOutsideSmoothstepBetween) {
  EXPECT_EQ(spotFalloff(0.95f, 0.8f, 0.9f), 1.0f);
  EXPECT_EQ(spotFalloff(0.9f, 0.8f, 0.9f), 1.0f);
  EXPECT_EQ(spotFalloff(0.7f, 0.8f, 0.9f), 0.0f);
  // Half way between the cones: s = 0.5, 0.25 * (3 - 1) = 0.5.
  EXPECT_NEAR(spotFalloff(0.85f, 0.8f, 0.9f), 0.5f, 1e-5f);
  // A quarter of the way: s = 0.25, 0.0625 * 2.5 = 0.15625.
  EXPECT_NEAR(spotFalloff(0.825f, 0.8f, 0.9f), 0.15625f, 1e-5f);
}

TEST(TransientPhysics, LambertianDirectIsAlbedoOverPiTimesIntensityCosOverR2) {
  // albedo 0.5, I = 2 W/sr, profile 1, cos 0.5, d = 2 m: 0.5/pi * 2 * 0.5/4.
  const vec3 l = lambertianDirect(vec3(0.5f, 0.25f, 1.0f), vec3(2.0f), 1.0f, 0.5f, 2.0f);
  const float expected = 0.5f / 3.14159265f * 2.0f * 0.125f;
  EXPECT_NEAR(l.x, expected, 1e-7f);
  EXPECT_NEAR(l.y, expected / 2.0f, 1e-7f);
  EXPECT_NEAR(l.z, expected * 2.0f, 1e-7f);
  // The profile scales it linearly.
  EXPECT_NEAR(lambertianDirect(vec3(0.5f), vec3(2.0f), 0.25f, 0.5f, 2.0f).x, expected / 4.0f,
              1e-7f);
}

TEST(TransientPhysics, GeometryTermIsCosCosOverR2ClampedWhenPositive) {
  EXPECT_FLOAT_EQ(geometryTerm(0.5f, 0.8f, 4.0f, 0.0f), 0.1f);
  EXPECT_FLOAT_EQ(geometryTerm(0.5f, 0.8f, 4.0f, -1.0f), 0.1f);  // <= 0: no clamp
  EXPECT_FLOAT_EQ(geometryTerm(0.5f, 0.8f, 4.0f, 0.05f), 0.05f);
  EXPECT_FLOAT_EQ(geometryTerm(1.0f, 1.0f, 1e-6f, 100.0f), 100.0f);
}

TEST(TransientPhysics, PathLengthsAddTheLegsInTheMedium) {
  EXPECT_FLOAT_EQ(directPathLength(1.5f, 2.0f, 3.0f), 7.5f);
  EXPECT_FLOAT_EQ(cameraPathLength(false, 1.5f, 2.0f), 3.0f);
  EXPECT_EQ(cameraPathLength(true, 1.5f, 2.0f), 0.0f);
  // VPL reached after 3 m (eta included), 2 m more in eta = 1.5, camera leg 1 m.
  EXPECT_FLOAT_EQ(vplPathLength(3.0f, 1.5f, 2.0f, 1.0f), 7.0f);
}

TEST(TransientPhysics, BinOfPathFloorsAndGoesNegativeBeforeTheAxis) {
  EXPECT_EQ(binOfPath(2.5f, 2.0f, 0.25f), 2);
  EXPECT_EQ(binOfPath(2.0f, 2.0f, 0.25f), 0);
  EXPECT_EQ(binOfPath(1.9f, 2.0f, 0.25f), -1);
  EXPECT_EQ(binOfPath(0.0f, 2.0f, 0.25f), -8);
  EXPECT_EQ(binOfPath(12.1f, 2.0f, 1.0f), 10);
}

}  // namespace
}  // namespace tofsim::physics
