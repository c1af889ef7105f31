// A lidar beam in a scattering medium (core/lidar BeamBackscatter.h): each
// bin of its waveform against the lidar equation's backscatter, P sigma_s
// p(pi) exp(-2 sigma_t s) / s^2 integrated densely over the bin's range
// (Simpson), per channel, from the overlap on and up to the surface; the
// fog's near return flagged as a false return, the surface's not; the same
// bytes on any thread count.
#include <gtest/gtest.h>

#include <cmath>

#include "support/AnalyticScenes.h"
#include "support/Simpson.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/lidar/BeamBackscatter.h"
#include "tofsim/lidar/LidarReturns.h"
#include "tofsim/lidar/ScanGrid.h"
#include "tofsim/lidar/ZoneWaveforms.h"
#include "tofsim/physics/MediumPhysics.h"

namespace tofsim::lidar {
namespace {

struct Wall {
  explicit Wall(float distance_m, float size_m = 40.0f)
      : scene(make(distance_m, size_m)), rays(scene, 1) {
    traced.rays = &rays;
    traced.materials = ir::materialVertices(scene, physics::VERTEX_LAMBERTIAN);
  }
  static scene::Scene make(float d, float size) {
    scene::Scene s;
    test::addQuad(s, glm::vec3(d, 0.0f, 0.0f), glm::vec3(-1, 0, 0), size, glm::vec3(0.5f));
    return s;
  }
  scene::Scene scene;
  rays::RayScene rays;
  WaveformScene traced;
};

// One beam along +x.
LidarSpec oneBeam() {
  LidarSpec s;
  s.elevations_deg = {0.0};
  s.azimuth_end_deg = 1.0;
  s.azimuth_step_deg = 1.0;
  s.power_W = 2.0;
  return s;
}

TimeAxis axisOf(double binWidth_s, int32_t bins) {
  TimeAxis axis;
  axis.bin_width_s = binWidth_s;
  axis.bins = bins;
  return axis;
}

TEST(LidarBackscatterTest, EachBinIsTheLidarEquationsBackscatter) {
  Wall wall(30.0f);
  capture::Medium& m = wall.traced.medium;
  m.sigma_s_per_m = glm::vec3(0.05f, 0.06f, 0.07f);
  m.sigma_a_per_m = glm::vec3(0.01f);
  m.phase = physics::PHASE_HENYEY_GREENSTEIN;
  m.g = 0.5f;
  const LidarSpec spec = oneBeam();
  const TimeAxis axis = axisOf(100e-12, 2800);  // 1.5 cm of range a bin, to 42 m
  LidarWaveforms w = renderDirectWaveforms(spec, wall.traced, axis, 1);
  const std::vector<float> direct = w.volume.values();
  addBackscatter(spec, wall.traced, axis, 1, w);
  // p(pi) of Henyey-Greenstein: (1 - g) / (4 pi (1 + g)^2).
  const double g = 0.5, p = (1.0 - g) / (4.0 * M_PI * (1.0 + g) * (1.0 + g));
  const double binRange = axis.bin_width_m() / 2.0, overlap = spec.backscatter.overlap_m;
  double worst = 0.0;
  int32_t compared = 0;
  for (int32_t k = 0; k < axis.bins; ++k) {
    const double a = std::max(k * binRange, overlap), b = std::min((k + 1) * binRange, 29.99);
    if (b > 29.9 || b <= a) {
      if (k * binRange < overlap) EXPECT_EQ(w.volume.values()[k], 0.0f) << "bin " << k;
      continue;
    }
    double expected = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double sigmaS = m.sigma_s_per_m[c], sigmaT = sigmaS + m.sigma_a_per_m[c];
      expected += spec.power_W * sigmaS * p / 3.0 *
                  test::simpson([&](double s) { return std::exp(-2.0 * sigmaT * s) / (s * s); },
                                a, b, 64);
    }
    const double got = double(w.volume.values()[k]) - direct[k];
    worst = std::max(worst, std::fabs(got / expected - 1.0));
    ++compared;
  }
  EXPECT_GT(compared, 1800);
  EXPECT_LT(worst, 2e-6);  // float bins
  // Nothing past the wall: the backscatter stops at it (the direct return's
  // bin aside), and the miss-free beam lost nothing after the axis.
  for (int32_t k = static_cast<int32_t>(30.01 / binRange); k < axis.bins; ++k) {
    EXPECT_EQ(w.volume.values()[k], 0.0f) << "bin " << k;
  }
  EXPECT_EQ(w.lost.after, 0.0);
}

TEST(LidarBackscatterTest, TheFogsNearReturnIsAFalseReturnTheWallsIsNot) {
  Wall wall(6.0f);
  wall.traced.medium.sigma_s_per_m = glm::vec3(0.2f);  // isotropic: p(pi) = 1 / (4 pi)
  LidarSpec spec = oneBeam();
  spec.power_W = 1.0;
  spec.returns.mode = ReturnMode::All;
  spec.returns.max = 4;
  spec.returns.threshold = 5e-5;  // the fog's bins from 1 m to ~1.5 m are above it
  const TimeAxis axis = axisOf(100e-12, 600);
  LidarWaveforms w = renderDirectWaveforms(spec, wall.traced, axis, 1);
  const BeamSurfaces surfaces = addBackscatter(spec, wall.traced, axis, 1, w);
  const LidarReturns r = lidarReturns(spec, w.volume, 10.0);
  const std::vector<uint8_t> fog = fogReturnFlags(spec, w.volume, surfaces);
  ASSERT_EQ(r.points.size(), 2u);
  ASSERT_EQ(fog.size(), 2u);
  EXPECT_EQ(fog[0], 1);  // the fog's, near the overlap
  EXPECT_LT(r.points[0].x, 1.6f);
  EXPECT_GT(r.points[0].x, 1.0f);
  EXPECT_EQ(fog[1], 0);  // the wall's
  EXPECT_NEAR(r.points[1].x, 6.0f, 0.02f);
  // Without the fog's scattering (absorption alone) nothing is added or flagged.
  wall.traced.medium.sigma_s_per_m = glm::vec3(0.0f);
  wall.traced.medium.sigma_a_per_m = glm::vec3(0.2f);
  LidarWaveforms clear = renderDirectWaveforms(spec, wall.traced, axis, 1);
  const std::vector<float> before = clear.volume.values();
  EXPECT_TRUE(addBackscatter(spec, wall.traced, axis, 1, clear).bins.empty());
  EXPECT_EQ(clear.volume.values(), before);
}

TEST(LidarBackscatterTest, TheSameBytesOnAnyThreadCount) {
  Wall wall(5.0f);
  wall.traced.medium.sigma_s_per_m = glm::vec3(0.1f);
  LidarSpec spec = oneBeam();
  spec.elevations_deg = {-20.0, 0.0, 20.0};
  spec.azimuth_end_deg = 360.0;
  spec.azimuth_step_deg = 2.0;
  const TimeAxis axis = axisOf(100e-12, 500);
  LidarWaveforms one = renderDirectWaveforms(spec, wall.traced, axis, 1);
  LidarWaveforms two = renderDirectWaveforms(spec, wall.traced, axis, 2);
  const BeamSurfaces a = addBackscatter(spec, wall.traced, axis, 1, one);
  const BeamSurfaces b = addBackscatter(spec, wall.traced, axis, 2, two);
  EXPECT_EQ(one.volume.values(), two.volume.values());
  EXPECT_EQ(a.bins, b.bins);
  EXPECT_EQ(one.lost.after, two.lost.after);
}

// A zone scan's flood (ScanGrid.h, BeamBackscatter.h): the flood's
// intensity power / Omega_fov in every direction, so a zone's receiver ray of
// solid angle Omega_ray collects power (Omega_ray / Omega_fov) sigma_s p(pi)
// exp(-2 sigma_t s) / s^2 ds: each bin of a zone is the lidar equation
// (Simpson) times the zone's share of the field, and that share is the
// zone's exact solid angle (a rectangle on the image plane) over the
// field's, within the sub-cells' midpoint rule.
TEST(LidarBackscatterTest, AZoneScansFloodBackscatterIsTheLidarEquationOverEachZone) {
  Wall wall(100.0f, 400.0f);  // past the axis: every zone ray in the fog throughout
  capture::Medium& m = wall.traced.medium;
  m.sigma_s_per_m = glm::vec3(0.05f);
  m.sigma_a_per_m = glm::vec3(0.01f);  // isotropic: p(pi) = 1 / (4 pi)
  LidarSpec spec;
  spec.scan = ScanPattern::Zones;
  spec.grid = {3, 4, 40.0, 30.0, 4};
  spec.power_W = 2.0;
  const TimeAxis axis = axisOf(100e-12, 1000);  // 1.5 cm a bin, to 15 m
  LidarWaveforms w = renderZoneWaveforms(spec, wall.traced, axis, 1);
  const std::vector<float> direct = w.volume.values();
  const BeamSurfaces surfaces = addBackscatter(spec, wall.traced, axis, 2, w);
  EXPECT_EQ(surfaces.raysPerBeam, 16);
  // The solid angle of [u0, u1] x [v0, v1] on the image plane at unit distance.
  const auto corner = [](double u, double v) { return std::atan(u * v / std::sqrt(1 + u * u + v * v)); };
  const auto rectangle = [&](double u0, double u1, double v0, double v1) {
    return corner(u1, v1) - corner(u0, v1) - corner(u1, v0) + corner(u0, v0);
  };
  const double tu = std::tan(glm::radians(20.0)), tv = std::tan(glm::radians(15.0));
  const double field = rectangle(-tu, tu, -tv, tv);
  const double p = 1.0 / (4.0 * M_PI), sigmaS = 0.05, sigmaT = 0.06;
  const double binRange = axis.bin_width_m() / 2.0, overlap = spec.backscatter.overlap_m;
  double worst = 0.0, shares = 0.0;
  for (int32_t row = 0; row < 3; ++row) {
    for (int32_t column = 0; column < 4; ++column) {
      double share = 0.0;
      for (const BeamRay& r : zoneRays(spec, row, column, fieldSolidAngle_sr(spec))) share += r.share;
      shares += share;
      const double exact = rectangle(tu * (column / 2.0 - 1.0), tu * ((column + 1) / 2.0 - 1.0),
                                     tv * (2.0 * row / 3.0 - 1.0), tv * (2.0 * (row + 1) / 3.0 - 1.0));
      EXPECT_NEAR(share, exact / field, 2e-3 * share) << "zone " << row << ", " << column;
      for (int32_t k = 0; k < axis.bins; ++k) {
        const double a = std::max(k * binRange, overlap), b = (k + 1) * binRange;
        const float got = w.volume.at(row, column, k, 0) - direct[w.volume.index(row, column, k, 0)];
        if (b <= a) {
          EXPECT_EQ(got, 0.0f) << "bin " << k;
          continue;
        }
        const double expected =
            share * spec.power_W * sigmaS * p *
            test::simpson([&](double s) { return std::exp(-2.0 * sigmaT * s) / (s * s); }, a, b, 64);
        worst = std::max(worst, std::fabs(got / expected - 1.0));
      }
    }
  }
  EXPECT_NEAR(shares, 1.0, 1e-6);  // the flood's whole power over the zones
  EXPECT_LT(worst, 2e-6);
}

}  // namespace
}  // namespace tofsim::lidar
