// Non-line-of-sight relay-wall captures (config `nlos:`), rendered by IR on
// the CPU backend, against the closed form of a hidden patch's third bounce
// (../shared/research/nlos-capture-format.md section 5), the time
// conventions, and the consistency of the three scan types.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "support/AnalyticScenes.h"
#include "tofsim/pipeline/NlosRender.h"
#include "tofsim/pipeline/NlosScan.h"
#include "tofsim/util/Error.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::pipeline {
namespace {

constexpr float kWallAlbedo = 0.5f, kPatchAlbedo = 0.8f;
constexpr float kPatchDistance = 0.4f, kPatchSide = 0.2f;

// A 1 m wall at z = 0 facing +z ("quad0") and a square patch facing it at z = r.
scene::Scene hiddenPatch() {
  scene::Scene s;
  test::addQuad(s, glm::vec3(0.0f), glm::vec3(0, 0, 1), 1.0f, glm::vec3(kWallAlbedo));
  test::addQuad(s, glm::vec3(0.0f, 0.0f, kPatchDistance), glm::vec3(0, 0, -1), kPatchSide,
                glm::vec3(kPatchAlbedo));
  return s;
}

config::RunConfig nlosConfig(config::NlosScan scan, int rsm) {
  config::RunConfig c;
  config::NlosConfig n;
  n.relay_wall = "quad0";
  n.scan = scan;
  n.sensor_grid = {3, 3};
  // Off to the side and nearer the wall than the patch, so that no line of
  // sight to a wall point crosses the patch.
  n.sensor_origin = {-0.8f, 0.0f, 0.3f};
  n.laser_origin = {-0.8f, 0.1f, 0.3f};
  c.nlos = n;
  c.render.time.start_s = 0.5 / kSpeedOfLight_m_per_s;  // 0.5 m of optical path
  c.render.time.bin_width_s = 0.01 / kSpeedOfLight_m_per_s;
  c.render.time.bins = 150;
  c.render.pixel_footprint = false;
  c.render.indirect.rsm_resolution = rsm;
  c.render.indirect.visibility = capture::Visibility::Exact;
  c.render.indirect.geometry_term_clamp_per_m2 = 0.0f;
  c.render.indirect.vpl_footprint = false;
  c.cpu_threads = 2;
  return c;
}

NlosVolume render(const config::RunConfig& c, const scene::Scene& s) {
  return renderNlosScan(c, s, planNlosScan(c, s));
}

// The closed form over the patch, cut into m x m elements: energy (summed
// over the bins and R, G, B) and energy-weighted mean optical path at
// confocal point s, for the collimated laser of 1 W per channel.
struct Expected {
  double energy = 0.0, meanPath_m = 0.0;
};
Expected closedForm(const glm::vec3& s) {
  const int m = 400;
  const double h = kPatchSide / m;
  const double rho = double(kWallAlbedo) * kPatchAlbedo * kWallAlbedo / (M_PI * M_PI * M_PI);
  Expected e;
  double weighted = 0.0;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      const glm::dvec3 x(-kPatchSide / 2 + (i + 0.5) * h, -kPatchSide / 2 + (j + 0.5) * h,
                         kPatchDistance);
      const glm::dvec3 d = x - glm::dvec3(s);
      const double r = glm::length(d);
      const double c = d.z / r;  // every cosine: wall (+z) and patch (-z) normals
      const double w = 3.0 * rho * std::pow(c, 4) / std::pow(r, 4) * h * h;
      e.energy += w;
      weighted += w * 2.0 * r;
    }
  }
  e.meanPath_m = weighted / e.energy;
  return e;
}

struct Measured {
  double energy = 0.0, meanPath_m = 0.0;
};
Measured measured(const NlosVolume& v, std::size_t point) {
  const std::size_t points = v.H.size() / v.axis.bins;
  Measured m;
  double weighted = 0.0;
  for (int32_t t = 0; t < v.axis.bins; ++t) {
    const double h = v.H[t * points + point];
    m.energy += h;
    weighted += h * (v.axis.start_m() + (t + 0.5) * v.axis.bin_width_m());
  }
  m.meanPath_m = weighted / m.energy;
  return m;
}

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
}

}  // namespace
}  // namespace tofsim::pipeline
