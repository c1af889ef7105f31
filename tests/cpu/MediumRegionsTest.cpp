// Issue 42's per-region media (`media:`): homogeneous media inside closed
// meshes, on the CPU backend and in the reference. A cube region 0.5 m thick
// between a camera (the light at its pinhole) and a plane: a pixel whose ray
// crosses the cube's top and bottom faces sees the plane's vacuum return
// times exp(-sigma_a x 2 x 0.5 / cos theta) (light and camera legs), delayed
// by (eta - 1) x that length (index_of_refraction); a pixel that misses the
// cube sees the vacuum's bytes. Single scattering in a slab region is the
// lidar equation restricted to the slab. Closed forms at pixel centres
// (render.pixel_footprint: false).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdio>

#include "RegionScenes.h"
#include "support/CpuRender.h"
#include "support/Simpson.h"
#include "support/TestJobs.h"
#include "tofsim/capture/MediumRegions.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/scene/RegionMeshes.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::cpu {
namespace {

using capture::RegionMedium;

using test::addBox;
using test::energy;
using test::renderReference;

constexpr float kTop = 1.0f, kBottom = 0.5f, kHalf = 0.25f;  // the cube over the plane

// The plane job with the cube region `tank` (sigma_a, eta) taken out of its
// surfaces, centre pixels, no indirect light.
struct TankJob {
  test::PlaneJob plane;
  TankJob(glm::vec3 sigmaA, double eta, bool withMedia = true) {
    addBox(plane.scene, "tank", {-kHalf, -kHalf, kBottom}, {kHalf, kHalf, kTop});
    auto region = scene::takeRegionMesh(plane.scene, "tank");
    EXPECT_TRUE(region.has_value());
    EXPECT_EQ(scene::regionMeshProblem(*region), "");
    plane.scene.regions.push_back(*region);
    capture::RenderJob& job = plane.job;
    job.camera().look_at_world = {0.0f, 0.0f, 0.0f};
    job.settings.pixel_footprint = false;
    job.settings.indirect.enabled = false;
    if (!withMedia) return;
    RegionMedium m;
    m.region = "tank";
    m.medium.sigma_a_per_m = sigmaA;
    m.index_of_refraction = eta;
    job.settings.media.push_back(m);
  }
};

// The length of pixel (x, y)'s centre ray inside the cube, or -1 where it
// crosses a side face (neither all in nor all out).
double insideLength(const capture::RenderJob& job, int x, int y) {
  const capture::PrimaryRay r = capture::PrimaryRays(job.imager).ray(x, y);
  const glm::dvec3 o(r.origin), d(glm::normalize(glm::dvec3(r.direction)));
  const auto within = [&](double z) {
    const glm::dvec3 p = o + d * ((z - o.z) / d.z);
    return std::abs(p.x) < kHalf && std::abs(p.y) < kHalf;
  };
  const bool top = within(kTop), bottom = within(kBottom);
  if (top && bottom) return (kTop - kBottom) / -d.z;
  return !top && !bottom ? 0.0 : -1.0;
}

double pixelSum(const TransientVolume& v, int x, int y, int c) {
  double sum = 0.0;
  for (int b = 0; b < v.bins(); ++b) sum += v.at(y, x, b, c);
  return sum;
}

int peakBin(const TransientVolume& v, int x, int y) {
  int best = 0;
  for (int b = 1; b < v.bins(); ++b) best = v.at(y, x, b, 0) > v.at(y, x, best, 0) ? b : best;
  return best;
}

// Pixels through the cube: vacuum x exp(-sigma_a 2 L) per channel; the
// others the vacuum's values.
void expectAbsorbedByTheCube(const TransientVolume& tank, const TransientVolume& vacuum,
                             const capture::RenderJob& job, glm::vec3 sigmaA) {
  int through = 0;
  for (int y = 0; y < vacuum.height(); ++y) {
    for (int x = 0; x < vacuum.width(); ++x) {
      const double inside = insideLength(job, x, y);
      if (inside < 0.0) continue;
      through += inside > 0.0;
      for (int c = 0; c < 3; ++c) {
        const double expected = pixelSum(vacuum, x, y, c) * std::exp(-2.0 * sigmaA[c] * inside);
        ASSERT_NEAR(pixelSum(tank, x, y, c), expected, 2e-6 * expected + 1e-12)
            << x << ", " << y << " channel " << c;
      }
    }
  }
  EXPECT_GT(through, 20);  // the closed form is tested where it matters
}

const glm::vec3 kSigmaA(1.0f, 0.5f, 0.2f);

TEST(MediumRegionsTest, RegionMeshesMustBeClosedAndConsistentlyWound) {
  scene::Scene s;
  addBox(s, "box", glm::vec3(0.0f), glm::vec3(1.0f));
  addBox(s, "inside_out", glm::vec3(2.0f), glm::vec3(3.0f), true);
  addBox(s, "open", glm::vec3(4.0f), glm::vec3(5.0f));
  s.meshes.back().indices.resize(s.meshes.back().indices.size() - 3);
  addBox(s, "twisted", glm::vec3(6.0f), glm::vec3(7.0f));
  std::swap(s.meshes.back().indices[1], s.meshes.back().indices[2]);
  EXPECT_EQ(scene::regionMeshProblem(*scene::takeRegionMesh(s, "box")), "");
  // Consistently wound inwards: turned out, closed.
  const auto turned = scene::takeRegionMesh(s, "inside_out");
  EXPECT_EQ(scene::regionMeshProblem(*turned), "");
  EXPECT_NE(scene::regionMeshProblem(*scene::takeRegionMesh(s, "open")).find("not closed"),
            std::string::npos);
  EXPECT_NE(scene::regionMeshProblem(*scene::takeRegionMesh(s, "twisted")).find("wound"),
            std::string::npos);
  EXPECT_FALSE(scene::takeRegionMesh(s, "missing").has_value());
  EXPECT_TRUE(s.meshes.empty());  // every region left the surfaces
}

TEST(MediumRegionsTest, PassageSumsTheLengthsInsideEachRegion) {
  scene::Scene s;
  addBox(s, "a", glm::vec3(0.0f), glm::vec3(1.0f));
  addBox(s, "b", glm::vec3(2.0f, 0.0f, 0.0f), glm::vec3(4.0f, 1.0f, 1.0f), true);
  for (const char* name : {"a", "b"}) s.regions.push_back(*scene::takeRegionMesh(s, name));
  RegionMedium a{"a", {}, 1.5}, b{"b", {}, 1.0};
  a.medium.sigma_a_per_m = glm::vec3(1.0f, 2.0f, 3.0f);
  b.medium.sigma_s_per_m = glm::vec3(0.5f);
  const capture::MediumRegions regions({a, b}, s, 1.0);
  // Through both along x at y = z = 0.5: the ray crosses a face's diagonal
  // (two triangles at one point, one crossing).
  const capture::RegionPassage p = regions.passage({-1.0, 0.5, 0.5}, {5.0, 0.5, 0.5});
  EXPECT_NEAR(p.opticalDepth.x, 1.0 + 2.0 * 0.5, 1e-12);
  EXPECT_NEAR(p.opticalDepth.z, 3.0 + 2.0 * 0.5, 1e-12);
  EXPECT_NEAR(p.extraPath_m, 0.5, 1e-12);
  // Starting inside a, ending inside b.
  const capture::RegionPassage q = regions.passage({0.25, 0.5, 0.5}, {3.0, 0.5, 0.5});
  EXPECT_NEAR(q.opticalDepth.y, 2.0 * 0.75 + 0.5, 1e-12);
  EXPECT_NEAR(q.extraPath_m, 0.375, 1e-12);
  // Beside both; and between them.
  EXPECT_EQ(regions.passage({-1.0, 2.0, 0.5}, {5.0, 2.0, 0.5}).opticalDepth, glm::dvec3(0.0));
  EXPECT_EQ(regions.passage({1.2, 0.5, 0.5}, {1.8, 0.5, 0.5}).opticalDepth, glm::dvec3(0.0));
}

TEST(MediumRegionsTest, AnAbsorbingCubeAttenuatesThePlanesReturnOnTheCpuBackend) {
  const TankJob tank(kSigmaA, 1.0), vacuum(kSigmaA, 1.0, false);
  const test::CpuRender withCube = test::renderOnCpu(tank.plane.job);
  const test::CpuRender without = test::renderOnCpu(vacuum.plane.job);
  expectAbsorbedByTheCube(withCube.volume.direct, without.volume.direct, tank.plane.job, kSigmaA);
}

TEST(MediumRegionsTest, AnAbsorbingCubeAttenuatesThePlanesReturnInTheReference) {
  const TankJob tank(kSigmaA, 1.0), vacuum(kSigmaA, 1.0, false);
  const capture::VolumeCollector withCube = renderReference(tank.plane.job, 1, 1);
  const capture::VolumeCollector without = renderReference(vacuum.plane.job, 1, 1);
  expectAbsorbedByTheCube(withCube.direct, without.direct, tank.plane.job, kSigmaA);
}

// eta 1.33 and no absorption: each through-pixel's peak moves by
// (eta - 1) x 2 L of path, in whole bins of the axis.
void expectDelayedByTheCube(const TransientVolume& tank, const TransientVolume& vacuum,
                            const capture::RenderJob& job) {
  const TimeAxis& axis = job.settings.time;
  const double eta = job.settings.media.front().index_of_refraction;
  int moved = 0;
  for (int y = 0; y < vacuum.height(); y += 3) {
    for (int x = 0; x < vacuum.width(); x += 3) {
      const double inside = insideLength(job, x, y);
      if (inside < 0.0) continue;
      const capture::PrimaryRay r = capture::PrimaryRays(job.imager).ray(x, y);
      const double vacuumPath = 2.0 * 1.5 / -glm::normalize(glm::dvec3(r.direction)).z;
      const double binOf = (vacuumPath + (eta - 1.0) * 2.0 * inside - axis.start_m()) /
                           axis.bin_width_m();
      if (std::abs(binOf - std::round(binOf)) < 0.01) continue;  // too near an edge to tell
      EXPECT_EQ(peakBin(tank, x, y), static_cast<int>(std::floor(binOf))) << x << ", " << y;
      moved += inside > 0.0;
    }
  }
  EXPECT_GT(moved, 2);
}

TEST(MediumRegionsTest, ARegionsIndexDelaysThePlanesPeakOnTheCpuBackend) {
  const TankJob tank(glm::vec3(0.0f), 1.33), vacuum(glm::vec3(0.0f), 1.0, false);
  expectDelayedByTheCube(test::renderOnCpu(tank.plane.job).volume.direct,
                         test::renderOnCpu(vacuum.plane.job).volume.direct, tank.plane.job);
}

TEST(MediumRegionsTest, ARegionsIndexDelaysThePlanesPeakInTheReference) {
  const TankJob tank(glm::vec3(0.0f), 1.33), vacuum(glm::vec3(0.0f), 1.0, false);
  expectDelayedByTheCube(renderReference(tank.plane.job, 1, 1).direct,
                         renderReference(vacuum.plane.job, 1, 1).direct, tank.plane.job);
}


// The corner (floor and wall) with an absorbing cube region in the light's
// and the camera's way: instant radiosity on the CPU backend against the
// reference, direct light and one indirect bounce. The direct light is exact
// in both (point pixels): the same energy to float rounding. The indirect
// light's absorption by the cube (its energy with the region over without)
// is the same within the reference's noise and the VPLs' bias, which both
// cancel mostly in the ratio.
TEST(MediumRegionsTest, InstantRadiosityMatchesTheReferenceThroughAnAbsorbingCube) {
  test::CornerJob corner(16);
  addBox(corner.scene, "cube", {-0.4f, 0.2f, -0.6f}, {0.4f, 0.8f, 0.2f});
  corner.scene.regions.push_back(*scene::takeRegionMesh(corner.scene, "cube"));
  capture::RenderJob vacuum = corner.job;
  vacuum.settings.pixel_footprint = false;
  vacuum.settings.indirect.rsm_resolution = 64;
  capture::RenderJob cube = vacuum;
  cube.settings.media.push_back({"cube", {}, 1.2});
  cube.settings.media.back().medium.sigma_a_per_m = {1.5f, 0.8f, 0.3f};
  const test::CpuRender irCube = test::renderOnCpu(cube), irVacuum = test::renderOnCpu(vacuum);
  const capture::VolumeCollector refCube = renderReference(cube, 2, 256),
                                 refVacuum = renderReference(vacuum, 2, 256);
  const double directIr = energy(irCube.volume.direct), directRef = energy(refCube.direct);
  EXPECT_NEAR(directIr, directRef, 1e-5 * directRef);
  EXPECT_LT(directIr, 0.95 * energy(irVacuum.volume.direct));  // the cube is in the way
  const double ratioIr = energy(irCube.volume.indirect) / energy(irVacuum.volume.indirect);
  const double ratioRef = energy(refCube.indirect) / energy(refVacuum.indirect);
  std::printf("indirect with the cube over without: IR %.4f, reference %.4f\n", ratioIr,
              ratioRef);
  EXPECT_LT(ratioIr, 0.95);
  EXPECT_NEAR(ratioIr, ratioRef, 0.02 * ratioRef);
}

// A camera with the light at its pinhole looking along +z through a slab
// region z in [51, 53] m (a box 10 m wide): the reference's single
// scattering per bin of one-way distance s is the lidar equation restricted
// to the slab, sigma_s p(pi) I exp(-2 sigma_t (s - 1)) / s^2 over s in
// [1, 3] m; nothing before or after it.
struct SlabJob {
  static constexpr double kS0 = 0.5, kBin = 0.25, kEnter = 1.0, kLeave = 3.0;
  scene::Scene scene = test::makePlane(1.0f, glm::vec3(0.0f));  // behind the camera
  capture::RenderJob job;
  capture::Medium medium;
  SlabJob() {
    addBox(scene, "slab", {-5.0f, -5.0f, 51.0f}, {5.0f, 5.0f, 53.0f});
    scene.regions.push_back(*scene::takeRegionMesh(scene, "slab"));
    job.scene = &scene;
    job.camera().position_world = job.light.position_world = {0.0f, 0.0f, 50.0f};
    job.camera().look_at_world = {0.0f, 0.0f, 60.0f};
    job.camera().fov_y_deg = 1.0f;
    job.camera().width = job.camera().height = 1;
    job.light.intensity_W_per_sr = {2.0f, 1.0f, 3.0f};
    const double perMetre = 2.0 / kSpeedOfLight_m_per_s;
    job.settings.time = TimeAxis{kS0 * perMetre, kBin * perMetre, 16};
    medium.sigma_a_per_m = {0.1f, 0.3f, 0.05f};
    medium.sigma_s_per_m = {0.3f, 0.2f, 0.5f};
    job.settings.media.push_back({"slab", medium, 1.0});
  }
};

// Chi-square of the render's bins against the slab's lidar equation with the
// slab entered at `enter` m (the truth: kEnter), per channel (the channels
// share their paths: their z are nearly equal, so each channel is a
// chi-square of its own over the slab's 8 bins, and the largest is
// returned), standard errors from the free flight's density in the slab (the
// equiangular points only lower the variance).
double slabChiSquare(const TransientVolume& v, const capture::Medium& m, double enter,
                     const glm::dvec3& intensity, double paths) {
  const double back = 1.0 / (4.0 * M_PI);  // isotropic
  const glm::dvec3 st(m.sigmaT());
  const auto pdf = [&](double s) {
    const glm::dvec3 e = glm::exp(-st * (s - SlabJob::kEnter));
    return (st.x * e.x + st.y * e.y + st.z * e.z) / 3.0;
  };
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    double chi2 = 0.0;
    for (int b = 0; b < v.bins(); ++b) {
      const double s0 = std::max(SlabJob::kS0 + b * SlabJob::kBin, SlabJob::kEnter);
      const double s1 = std::min(SlabJob::kS0 + (b + 1) * SlabJob::kBin, SlabJob::kLeave);
      if (!(s1 > s0)) {
        EXPECT_EQ(v.at(0, 0, b, c), 0.0f) << "bin " << b << " outside the slab";
        continue;
      }
      const auto f = [&](double s) {
        return m.sigma_s_per_m[c] * back * intensity[c] * std::exp(-2.0 * st[c] * (s - enter)) /
               (s * s);
      };
      const double mean = test::simpson(f, s0, s1);
      const double second = test::simpson([&](double s) { return f(s) * f(s) / pdf(s); }, s0, s1);
      const double z = (v.at(0, 0, b, c) - mean) / std::sqrt((second - mean * mean) / paths);
      chi2 += z * z;
    }
    worst = std::max(worst, chi2);
  }
  return worst;
}

TEST(MediumRegionsTest, SingleScatteringInASlabRegionIsTheLidarEquationRestrictedToIt) {
  constexpr int kPaths = 16384;
  SlabJob s;
  const capture::VolumeCollector out = renderReference(s.job, 1, kPaths);
  const glm::dvec3 intensity(s.job.light.intensity_W_per_sr);
  const double df = 8;  // the slab's 8 bins
  const double critical = df + 5.0 * std::sqrt(2.0 * df);
  const double chi2 = slabChiSquare(out.direct, s.medium, SlabJob::kEnter, intensity, kPaths);
  EXPECT_LT(chi2, critical);
  // The medium's transmittance counted from the camera (a medium filling the
  // scene up to the slab's far side) is rejected by the same bins.
  const double chi2Off = slabChiSquare(out.direct, s.medium, 0.0, intensity, kPaths);
  EXPECT_GT(chi2Off, critical);
  std::printf("slab: chi-square %.1f (the worst channel's 8 bins, critical %.1f), from the "
              "camera: %.0f\n",
              chi2, critical, chi2Off);
}

}  // namespace
}  // namespace tofsim::cpu
