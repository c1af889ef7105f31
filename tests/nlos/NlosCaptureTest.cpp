// Non-line-of-sight relay-wall captures (config `nlos:`), rendered by IR on
// the CPU backend, against the closed form of a hidden patch's third bounce
// (../shared/research/nlos-capture-format.md section 5), the time
// conventions, and the consistency of the three scan types.

#include <gtest/gtest.h>

#include <cstring>
#include <utility>
#include <vector>

#include "HiddenPatch.h"
#include "tofsim/pipeline/NlosRender.h"
#include "tofsim/physics/TemporalResponse.h"
#include "tofsim/pipeline/NlosScan.h"
#include "tofsim/util/Error.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::pipeline {
namespace {

using namespace test;  // the hidden patch, its config and closed form

TEST(NlosCaptureTest, ConfocalPatchFollowsTheThirdBounceClosedForm) {
  const scene::Scene s = hiddenPatch();
  const config::RunConfig c = nlosConfig(config::NlosScan::Confocal, 512);
  const NlosScanGeometry scan = planNlosScan(c, s);
  const NlosVolume v = renderNlosScan(c, s, scan);
  ASSERT_EQ(v.shape, (std::vector<std::size_t>{150, 3, 3}));
  EXPECT_EQ(v.captures, 9u);
  double lawRatioMin = 1e9, lawRatioMax = 0.0;
  for (std::size_t p = 0; p < 9; ++p) {
    const Expected e = closedForm(scan.sensorPoints[p]);
    const Measured m = measured(v, p);
    SCOPED_TRACE("point " + std::to_string(p));
    EXPECT_NEAR(m.energy / e.energy, 1.0, 0.02);
    EXPECT_NEAR(m.meanPath_m, e.meanPath_m, 0.005);  // half a bin
    lawRatioMin = std::min(lawRatioMin, m.energy / e.energy);
    lawRatioMax = std::max(lawRatioMax, m.energy / e.energy);
    // Nothing before the nearest patch point's path 2 |x - s|.
    const double nearest =
        2.0 *
        std::sqrt(std::pow(std::max(0.0f, std::abs(scan.sensorPoints[p].x) - kPatchSide / 2), 2) +
                  std::pow(std::max(0.0f, std::abs(scan.sensorPoints[p].y) - kPatchSide / 2), 2) +
                  kPatchDistance * kPatchDistance);
    const std::size_t points = 9;
    for (int32_t t = 0; t < v.axis.bins; ++t) {
      if (v.axis.start_m() + (t + 1) * v.axis.bin_width_m() <= nearest - 1e-6) {
        EXPECT_EQ(v.H[t * points + p], 0.0f) << "bin " << t << " before the first arrival";
      }
    }
  }
  // The centre point sees the patch head on, the corners at ~40 degrees: the
  // law's cos^4 / r^4 spans a factor of ~10 over the scan, the ratio to it
  // stays flat.
  EXPECT_LT(lawRatioMax - lawRatioMin, 0.02);
  EXPECT_GT(closedForm(scan.sensorPoints[4]).energy / closedForm(scan.sensorPoints[0]).energy, 5.0);
}

TEST(NlosCaptureTest, CountingTheFirstAndLastLegsShiftsEveryArrivalByThem) {
  const scene::Scene s = hiddenPatch();
  config::RunConfig c = nlosConfig(config::NlosScan::Confocal, 128);
  c.render.time.bins = 400;
  const NlosScanGeometry scan = planNlosScan(c, s);
  const NlosVolume without = renderNlosScan(c, s, scan);
  c.nlos->account_first_and_last_bounces = true;
  const NlosVolume with = renderNlosScan(c, s, scan);
  for (std::size_t p = 0; p < 9; ++p) {
    const glm::vec3 x = scan.sensorPoints[p];
    const double legs = glm::length(scan.laserOrigin - x) + glm::length(x - scan.sensorOrigin);
    const Measured a = measured(without, p), b = measured(with, p);
    EXPECT_NEAR(b.meanPath_m - a.meanPath_m, legs, 0.002) << "point " << p;
    EXPECT_NEAR(b.energy / a.energy, 1.0, 1e-4) << "point " << p;
  }
}

TEST(NlosCaptureTest, ADelayedHiddenPatchReturnsItsLightLaterByItsMeanDelay) {
  scene::Scene s = hiddenPatch();
  const config::RunConfig c = nlosConfig(config::NlosScan::Confocal, 64);
  const NlosVolume instant = render(c, s);
  // A lifetime of 5 bins (5 cm of path), half the patch's light delayed: the
  // third bounce's mean path moves by 2.5 cm, exactly in bin indices, and
  // its energy is kept (the tail past the axis is e^(-18)).
  const double tau_m = 0.05, f = 0.5;
  physics::ResponseKernel k;
  k.lifetime_s = tau_m / kSpeedOfLight_m_per_s;
  k.fraction = f;
  s.materials[1].scatteringDelay = k;
  const NlosVolume delayed = render(c, s);
  for (std::size_t p = 0; p < 9; ++p) {
    const Measured a = measured(instant, p), b = measured(delayed, p);
    EXPECT_NEAR(b.meanPath_m - a.meanPath_m, f * tau_m, 1e-4) << "point " << p;
    EXPECT_NEAR(b.energy / a.energy, 1.0, 1e-5) << "point " << p;
  }
}

bool sameBytes(const float* a, const float* b, std::size_t n) {
  return std::memcmp(a, b, n * sizeof(float)) == 0;
}

TEST(NlosCaptureTest, ConfocalIsTheExhaustiveDiagonalAndSingleIsItsRow) {
  const scene::Scene s = hiddenPatch();
  const NlosVolume confocal = render(nlosConfig(config::NlosScan::Confocal, 64), s);
  config::RunConfig ex = nlosConfig(config::NlosScan::Exhaustive, 64);
  ex.nlos->laser_grid = {3, 3};
  const NlosVolume exhaustive = render(ex, s);
  ASSERT_EQ(exhaustive.shape, (std::vector<std::size_t>{150, 3, 3, 3, 3}));
  double energy = 0.0;
  for (int32_t t = 0; t < 150; ++t) {
    for (std::size_t p = 0; p < 9; ++p) {
      // H[t, lx, ly, sx, sy] with (lx, ly) = (sx, sy) = point p.
      EXPECT_EQ(exhaustive.H[(t * 9 + p) * 9 + p], confocal.H[t * 9 + p]);
      energy += confocal.H[t * 9 + p];
    }
  }
  EXPECT_GT(energy, 0.0);
  // single at the wall's centre = the exhaustive scan with one laser point there.
  config::RunConfig one = ex;
  one.nlos->laser_grid = {1, 1};
  const NlosVolume row = render(one, s);
  config::RunConfig single = nlosConfig(config::NlosScan::Single, 64);
  const NlosVolume centre = render(single, s);
  ASSERT_EQ(centre.shape, (std::vector<std::size_t>{150, 3, 3}));
  ASSERT_EQ(row.H.size(), centre.H.size());
  EXPECT_TRUE(sameBytes(row.H.data(), centre.H.data(), row.H.size()));
  // and that laser point is the confocal scan's centre point: the diagonal again.
  for (int32_t t = 0; t < 150; ++t) EXPECT_EQ(centre.H[t * 9 + 4], confocal.H[t * 9 + 4]);
}

TEST(NlosCaptureTest, SameBytesOnOneThreadAndTwoAndTheSceneIsPreparedOncePerRenderer) {
  const scene::Scene s = hiddenPatch();
  config::RunConfig c = nlosConfig(config::NlosScan::Confocal, 64);
  c.cpu_threads = 1;
  const NlosVolume one = render(c, s);
  EXPECT_EQ(one.scenePreparations, 1u);  // nine captures, one renderer
  c.cpu_threads = 2;
  const NlosVolume two = render(c, s);
  EXPECT_LE(two.scenePreparations, 2u);
  ASSERT_EQ(one.H.size(), two.H.size());
  EXPECT_TRUE(sameBytes(one.H.data(), two.H.data(), one.H.size()));
}

void expectInputError(const config::RunConfig& c, const scene::Scene& s, const std::string& key) {
  try {
    planNlosScan(c, s);
    ADD_FAILURE() << "no error for " << key;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}

TEST(NlosCaptureTest, AMissingCurvedOrFlatWallOrAnOriginBehindItIsAnErrorAtItsKey) {
  const scene::Scene s = hiddenPatch();
  config::RunConfig c = nlosConfig(config::NlosScan::Confocal, 16);
  c.nlos->relay_wall = "no_such_wall";
  expectInputError(c, s, "nlos.relay_wall");
  c = nlosConfig(config::NlosScan::Confocal, 16);
  c.nlos->laser_origin = {0.0f, 0.0f, -1.0f};
  expectInputError(c, s, "nlos.laser_origin");
  c = nlosConfig(config::NlosScan::Confocal, 16);
  c.nlos->sensor_origin = {0.3f, 0.0f, 0.0f};  // in the wall's plane
  expectInputError(c, s, "nlos.sensor_origin");
  scene::Scene bent = hiddenPatch();
  bent.meshes[0].positions_world[2].z += 0.1f;
  expectInputError(nlosConfig(config::NlosScan::Confocal, 16), bent, "not planar");
  scene::Scene line = hiddenPatch();
  for (glm::vec3& p : line.meshes[0].positions_world) p.y = 0.0f;
  expectInputError(nlosConfig(config::NlosScan::Confocal, 16), line, "no area");
  // Flat, its two triangles wound opposite ways: no side faces the scene.
  scene::Scene flipped = hiddenPatch();
  ASSERT_EQ(flipped.meshes[0].indices.size(), 6u);
  std::swap(flipped.meshes[0].indices[4], flipped.meshes[0].indices[5]);
  expectInputError(nlosConfig(config::NlosScan::Confocal, 16), flipped, "no front face");
}

}  // namespace
}  // namespace tofsim::pipeline
