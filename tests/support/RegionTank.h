#pragma once
// Issue 42's per-region media on a cube region, as the IR backends and the
// reference are tested on it (tests/cpu/MediumRegionsTest.cpp,
// tests/gl/MediumRegionsGLTest.cpp): a cube region 0.5 m thick between a
// camera (the light at its pinhole) and a plane: a pixel whose ray crosses
// the cube's top and bottom faces sees the plane's vacuum return times
// exp(-sigma_a x 2 x 0.5 / cos theta) (light and camera legs), delayed by
// (eta - 1) x that length (index_of_refraction); a pixel that misses the
// cube sees the vacuum's bytes. And the corner with an absorbing cube in the
// light's and the camera's way, for IR against the reference. Closed forms
// at pixel centres (render.pixel_footprint: false).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "support/ClosedForm.h"
#include "support/RegionScenes.h"
#include "support/TestJobs.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/capture/MediumRegions.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/scene/RegionMeshes.h"

namespace tofsim::test {

using capture::RegionMedium;

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
inline double insideLength(const capture::RenderJob& job, int x, int y) {
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

inline double pixelSum(const TransientVolume& v, int x, int y, int c) {
  double sum = 0.0;
  for (int b = 0; b < v.bins(); ++b) sum += v.at(y, x, b, c);
  return sum;
}


// Pixels through the cube: vacuum x exp(-sigma_a 2 L) per channel (to `tol`,
// relative); the others the vacuum's values.
inline void expectAbsorbedByTheCube(const TransientVolume& tank, const TransientVolume& vacuum,
                                    const capture::RenderJob& job, glm::vec3 sigmaA,
                                    double tol = 2e-6) {
  int through = 0;
  for (int y = 0; y < vacuum.height(); ++y) {
    for (int x = 0; x < vacuum.width(); ++x) {
      const double inside = insideLength(job, x, y);
      if (inside < 0.0) continue;
      through += inside > 0.0;
      for (int c = 0; c < 3; ++c) {
        const double expected = pixelSum(vacuum, x, y, c) * std::exp(-2.0 * sigmaA[c] * inside);
        ASSERT_NEAR(pixelSum(tank, x, y, c), expected, tol * expected + 1e-12)
            << x << ", " << y << " channel " << c;
      }
    }
  }
  EXPECT_GT(through, 20);  // the closed form is tested where it matters
}

// eta 1.33 and no absorption: each through-pixel's peak moves by
// (eta - 1) x 2 L of path, in whole bins of the axis.
inline void expectDelayedByTheCube(const TransientVolume& tank, const TransientVolume& vacuum,
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
      EXPECT_EQ(peakBin(tank, y, x), static_cast<int>(std::floor(binOf))) << x << ", " << y;
      moved += inside > 0.0;
    }
  }
  EXPECT_GT(moved, 2);
}


// The corner (floor and wall) with an absorbing cube region in the light's
// and the camera's way: instant radiosity (`renderIr`: the backend's volumes)
// against the reference, direct light and one indirect bounce. The direct
// light is exact in both (point pixels): the same energy to float rounding
// (`directTol`, relative). The indirect light's absorption by the cube (its
// energy with the region over without) is the same within the reference's
// noise and the VPLs' bias, which both cancel mostly in the ratio.
inline void expectIrMatchesReferenceThroughACube(
    const std::function<capture::VolumeCollector(const capture::RenderJob&)>& renderIr,
    double directTol) {
  CornerJob corner(16);
  addBox(corner.scene, "cube", {-0.4f, 0.2f, -0.6f}, {0.4f, 0.8f, 0.2f});
  corner.scene.regions.push_back(*scene::takeRegionMesh(corner.scene, "cube"));
  capture::RenderJob vacuum = corner.job;
  vacuum.settings.pixel_footprint = false;
  vacuum.settings.indirect.rsm_resolution = 64;
  capture::RenderJob cube = vacuum;
  cube.settings.media.push_back({"cube", {}, 1.2});
  cube.settings.media.back().medium.sigma_a_per_m = {1.5f, 0.8f, 0.3f};
  const capture::VolumeCollector irCube = renderIr(cube), irVacuum = renderIr(vacuum);
  const capture::VolumeCollector refCube = renderReference(cube, 2, 256),
                                 refVacuum = renderReference(vacuum, 2, 256);
  const double directIr = energy(irCube.direct), directRef = energy(refCube.direct);
  EXPECT_NEAR(directIr, directRef, directTol * directRef);
  EXPECT_LT(directIr, 0.95 * energy(irVacuum.direct));  // the cube is in the way
  const double ratioIr = energy(irCube.indirect) / energy(irVacuum.indirect);
  const double ratioRef = energy(refCube.indirect) / energy(refVacuum.indirect);
  std::printf("indirect with the cube over without: IR %.4f, reference %.4f\n", ratioIr,
              ratioRef);
  EXPECT_LT(ratioIr, 0.95);
  EXPECT_NEAR(ratioIr, ratioRef, 0.02 * ratioRef);
}

}  // namespace tofsim::test
