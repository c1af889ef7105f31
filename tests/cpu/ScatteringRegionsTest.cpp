// Issue 42's per-region media in instant radiosity beyond absorption and one
// bounce (CPU backend): a scattering region's single scattering along the
// camera rays (CpuRegionDirect.cpp) against the lidar equation restricted to
// the ray's segment inside a cube, and against the reference on a corner; its
// medium VPLs and their light in the camera rays against the reference's
// second vertex; the later bounces' VPL legs through an absorbing region
// (ir::traceBounce) against a slab's closed form and the reference's bounces
// 2 and 3; the same bytes on any thread count. Closed forms at pixel centres
// (render.pixel_footprint: false).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "support/RegionScenes.h"
#include "support/CpuRender.h"
#include "support/Simpson.h"
#include "support/TestJobs.h"
#include "tofsim/ir/BounceVpls.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/physics/ScatterVertex.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/scene/RegionMeshes.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::cpu {
namespace {

using test::addBox;
using test::energy;
using test::renderReference;

// A one-pixel camera with the light at its pinhole, 1.5 m above the plane
// (z = 0) looking straight down through a cube region z in [0.5, 1] m: its
// ray is in the cube for s in [0.5, 1] m of one-way distance. The axis in
// metres of optical path: 0.51 .. 4.51 m, 5 cm bins (no edge on the
// segment's ends nor the plane).
struct CubeRayJob {
  static constexpr double kStart = 0.51, kBin = 0.05, kEnter = 0.5, kLeave = 1.0, kPlane = 1.5;
  test::PlaneJob plane;
  capture::Medium medium;
  double eta;
  CubeRayJob(double indexOfRefraction, bool withMedium = true) : eta(indexOfRefraction) {
    addBox(plane.scene, "cube", {-0.25f, -0.25f, 0.5f}, {0.25f, 0.25f, 1.0f});
    plane.scene.regions.push_back(*scene::takeRegionMesh(plane.scene, "cube"));
    capture::RenderJob& job = plane.job;
    job.camera().look_at_world = {0.0f, 0.0f, 0.0f};
    job.camera().width = job.camera().height = 1;
    job.camera().fov_y_deg = 1.0f;
    job.settings.pixel_footprint = false;
    job.settings.indirect.enabled = false;
    job.settings.time =
        TimeAxis{kStart / kSpeedOfLight_m_per_s, kBin / kSpeedOfLight_m_per_s, 80};
    medium.sigma_a_per_m = {0.3f, 0.6f, 0.1f};
    medium.sigma_s_per_m = {0.8f, 0.4f, 1.2f};
    medium.phase = physics::PHASE_HENYEY_GREENSTEIN;
    medium.g = 0.4f;
    if (withMedium) job.settings.media.push_back({"cube", medium, eta});
  }
};

// The cube's single scattering in bin b, channel c: the lidar equation
// sigma_s p(pi) I exp(-2 sigma_t (s - enter)) / s^2 over the s whose path
// 2 s + 2 (eta - 1)(s - enter) (both legs delayed inside the cube) is in the
// bin, within the cube's segment.
double restrictedLidarEquation(const CubeRayJob& j, int b, int c) {
  const glm::dvec3 intensity(j.plane.job.light.intensity_W_per_sr);
  const double back = physics::phaseFunction(j.medium.phase, j.medium.g, -1.0f);
  const double sigmaT = j.medium.sigmaT()[c], delta = j.eta - 1.0;
  const auto sOf = [&](double q) { return (0.5 * q + delta * CubeRayJob::kEnter) / (1.0 + delta); };
  const double s0 = std::max(sOf(CubeRayJob::kStart + b * CubeRayJob::kBin), CubeRayJob::kEnter);
  const double s1 =
      std::min(sOf(CubeRayJob::kStart + (b + 1) * CubeRayJob::kBin), CubeRayJob::kLeave);
  return test::simpson(
      [&](double s) {
        return j.medium.sigma_s_per_m[c] * back * intensity[c] *
               std::exp(-2.0 * sigmaT * (s - CubeRayJob::kEnter)) / (s * s);
      },
      s0, s1);
}

// IR's direct light along the ray: the cube's single scattering in every bin
// its segment reaches, zero elsewhere but the plane's bin, whose return is
// the vacuum's times exp(-2 sigma_t L), (eta - 1) 2 L of path later.
void expectTheRestrictedLidarEquation(double eta) {
  SCOPED_TRACE("eta " + std::to_string(eta));
  const CubeRayJob cube(eta), vacuum(eta, false);
  const TransientVolume ir = test::renderOnCpu(cube.plane.job).volume.direct;
  const TransientVolume air = test::renderOnCpu(vacuum.plane.job).volume.direct;
  const double planePath = 2.0 * CubeRayJob::kPlane + 2.0 * (eta - 1.0) * 0.5;
  const int planeBin =
      static_cast<int>(std::floor((planePath - CubeRayJob::kStart) / CubeRayJob::kBin));
  int lit = 0;
  for (int b = 0; b < ir.bins(); ++b) {
    for (int c = 0; c < 3; ++c) {
      const double got = ir.at(0, 0, b, c);
      if (b == planeBin) {
        double vacuumReturn = 0.0;  // in the vacuum's own (earlier) bin
        for (int a = 0; a < air.bins(); ++a) vacuumReturn += air.at(0, 0, a, c);
        const double expected = vacuumReturn * std::exp(-2.0 * cube.medium.sigmaT()[c] * 0.5);
        EXPECT_GT(expected, 0.0);
        EXPECT_NEAR(got, expected, 1e-5 * expected) << "the plane's bin " << b << ", channel " << c;
        continue;
      }
      const double expected = restrictedLidarEquation(cube, b, c);
      lit += c == 0 && expected > 0.0;
      EXPECT_NEAR(got, expected, 2e-4 * expected + 1e-12) << "bin " << b << ", channel " << c;
    }
  }
  // The segment's path 1 .. 2 + 2 (eta - 1) x 0.5 m: 20 bins and more.
  EXPECT_GE(lit, 20);
}

TEST(ScatteringRegionsTest, ACubesSingleScatteringIsTheLidarEquationRestrictedToItsSegment) {
  expectTheRestrictedLidarEquation(1.0);
}

TEST(ScatteringRegionsTest, ACubesIndexDelaysItsSingleScatteringOnBothLegs) {
  expectTheRestrictedLidarEquation(1.33);
}

// The energy-weighted mean of a volume's optical path, metres.
double meanPath_m(const TransientVolume& v, const TimeAxis& axis) {
  double sum = 0.0, weighted = 0.0;
  for (int y = 0; y < v.height(); ++y) {
    for (int x = 0; x < v.width(); ++x) {
      for (int b = 0; b < v.bins(); ++b) {
        const double e = static_cast<double>(v.at(y, x, b, 0)) + v.at(y, x, b, 1) + v.at(y, x, b, 2);
        sum += e;
        weighted += e * (axis.start_m() + (b + 0.5) * axis.bin_width_m());
      }
    }
  }
  return weighted / sum;
}

// The corner (floor and wall) with a scattering cube region between the light
// and the surfaces, the camera looking through it.
struct ScatteringCornerJob {
  test::CornerJob corner{16};
  capture::RenderJob job;
  explicit ScatteringCornerJob(bool withMedium = true) {
    addBox(corner.scene, "cube", {-0.4f, 0.2f, -0.6f}, {0.4f, 0.8f, 0.2f});
    corner.scene.regions.push_back(*scene::takeRegionMesh(corner.scene, "cube"));
    job = corner.job;
    job.settings.pixel_footprint = false;
    job.settings.indirect.enabled = false;
    if (!withMedium) return;
    capture::RegionMedium m{"cube", {}, 1.4};
    m.medium.sigma_a_per_m = {0.4f, 0.2f, 0.1f};
    m.medium.sigma_s_per_m = {1.5f, 2.0f, 2.5f};
    m.medium.phase = physics::PHASE_HENYEY_GREENSTEIN;
    m.medium.g = 0.3f;
    job.settings.media.push_back(m);
  }
};

// IR's direct light (the surfaces' through the region, the region's single
// scattering) against the reference's first vertex (the same light by free
// flights and equiangular points through the region), over the image: the
// energy within 1 % and the mean path within 1 mm (the reference's noise at
// 2048 paths a pixel: ~0.3 % and ~0.5 mm). Without the region's single
// scattering IR has 0.64 of the energy; without its delay the mean path is
// 3 cm short.
TEST(ScatteringRegionsTest, DirectLightThroughAScatteringCubeMatchesTheReference) {
  const ScatteringCornerJob s;
  const TransientVolume ir = test::renderOnCpu(s.job).volume.direct;
  const TransientVolume ref = renderReference(s.job, 1, 2048).direct;
  const double eIr = energy(ir), eRef = energy(ref);
  const TimeAxis& axis = s.job.settings.time;
  const double pIr = meanPath_m(ir, axis), pRef = meanPath_m(ref, axis);
  std::printf("direct through the scattering cube: energy IR %.6g, reference %.6g (%.4f); mean "
              "path IR %.5f m, reference %.5f m\n",
              eIr, eRef, eIr / eRef, pIr, pRef);
  EXPECT_NEAR(eIr, eRef, 0.01 * eRef);
  EXPECT_NEAR(pIr, pRef, 0.001);
}

// The scattering cube's multiple scattering, one indirect bounce (the
// reference's second vertex): the light's medium VPLs in the cube
// (ir::lightRegionVpls) and the RSM's light the surfaces and, scattered once
// more, the camera rays' stretches in the cube (CpuRegionVpls.cpp). Without
// the geometry clamp (as configs/fog_box.yaml: the clamp's radius, 0.1 m at
// the default, is much of the cube) and with 65,536 rays for the medium VPLs,
// exact visibility. IR's indirect energy with the cube over the vacuum's
// against the reference's (the VPLs' bias cancels mostly in the ratio) within
// 3 % (measured: 1.2370 against 1.2526, the vacuums 7.161 and 7.127), its
// mean path within 1.5 cm (5.1035 against 5.0969 m). Without the medium VPLs
// IR's ratio is 0.69, without the camera rays' pass 0.81.
TEST(ScatteringRegionsTest, OneBounceThroughAScatteringCubeMatchesTheReference) {
  ScatteringCornerJob s, vacuum(false);
  for (capture::RenderJob* job : {&s.job, &vacuum.job}) {
    job->settings.indirect.enabled = true;
    job->settings.indirect.rsm_resolution = 48;
    job->settings.indirect.medium_vpls = 65536;
    job->settings.indirect.geometry_term_clamp_per_m2 = 0.0;
    job->settings.indirect.visibility = capture::Visibility::Exact;
  }
  const TransientVolume irCube = test::renderOnCpu(s.job).volume.indirect;
  const TransientVolume irVacuum = test::renderOnCpu(vacuum.job).volume.indirect;
  const TransientVolume refCube = renderReference(s.job, 2, 1024).indirect;
  const TransientVolume refVacuum = renderReference(vacuum.job, 2, 1024).indirect;
  const double ratioIr = energy(irCube) / energy(irVacuum);
  const double ratioRef = energy(refCube) / energy(refVacuum);
  const TimeAxis& axis = s.job.settings.time;
  const double pIr = meanPath_m(irCube, axis), pRef = meanPath_m(refCube, axis);
  std::printf("indirect with the scattering cube over without: IR %.4f, reference %.4f; mean "
              "path IR %.4f m, reference %.4f m (vacuum IR %.6g, reference %.6g)\n",
              ratioIr, ratioRef, pIr, pRef, energy(irVacuum), energy(refVacuum));
  EXPECT_NEAR(ratioIr, ratioRef, 0.03 * ratioRef);
  EXPECT_NEAR(pIr, pRef, 0.015);
}

// The corner with an absorbing cube in the light's and the camera's way, three
// bounces: the later bounces' VPLs are shot through the cube too. IR's bounces
// 2 + 3 with the cube over without against the reference's (vertices 3 and 4:
// its indirect light at 4 vertices less at 2), each ratio of the same scene's
// renders, which cancels the VPLs' bias and most of the reference's noise.
TEST(ScatteringRegionsTest, LaterBouncesThroughAnAbsorbingCubeMatchTheReference) {
  test::CornerJob corner(12);
  addBox(corner.scene, "cube", {-0.4f, 0.2f, -0.6f}, {0.4f, 0.8f, 0.2f});
  corner.scene.regions.push_back(*scene::takeRegionMesh(corner.scene, "cube"));
  capture::RenderJob vacuum = corner.job;
  vacuum.settings.pixel_footprint = false;
  vacuum.settings.indirect.rsm_resolution = 48;
  vacuum.settings.indirect.bounces = 3;
  // Bounces 2 and 3 are random rays: enough of them that IR's own noise is
  // ~1 % (2,304 give ~8 %).
  vacuum.settings.indirect.vpls_per_bounce = 32768;
  capture::RenderJob cube = vacuum;
  cube.settings.media.push_back({"cube", {}, 1.2});
  cube.settings.media.back().medium.sigma_a_per_m = {1.5f, 0.8f, 0.3f};
  // Energy and energy x path (the axis' metres) of bounces 2 + 3.
  struct Later {
    double energy = 0.0, weighted = 0.0;
    void add(const TransientVolume& v, const TimeAxis& axis, double sign) {
      for (int y = 0; y < v.height(); ++y) {
        for (int x = 0; x < v.width(); ++x) {
          for (int b = 0; b < v.bins(); ++b) {
            const double e =
                static_cast<double>(v.at(y, x, b, 0)) + v.at(y, x, b, 1) + v.at(y, x, b, 2);
            energy += sign * e;
            weighted += sign * e * (axis.start_m() + (b + 0.5) * axis.bin_width_m());
          }
        }
      }
    }
  };
  const auto laterIr = [](const capture::RenderJob& job) {
    capture::VolumeCollector out(job.camera().width, job.camera().height, job.settings.time,
                                 capture::kChannels, 3);
    // Nothing in the corner hides a surface from another (the cube is no
    // surface): every VPL sees every point, the visibility test is skipped.
    ir::IrRenderer(std::make_unique<CpuBackend>(CpuBackendOptions{2, false})).render(job, out);
    Later l;
    for (int k = 1; k < 3; ++k) l.add(out.bounces[k], job.settings.time, 1.0);
    return l;
  };
  const auto laterRef = [](const capture::RenderJob& job) {
    Later l;
    l.add(renderReference(job, 4, 512).indirect, job.settings.time, 1.0);
    l.add(renderReference(job, 2, 512).indirect, job.settings.time, -1.0);
    return l;
  };
  const Later irCube = laterIr(cube), refCube = laterRef(cube);
  const double ratioIr = irCube.energy / laterIr(vacuum).energy;
  const double ratioRef = refCube.energy / laterRef(vacuum).energy;
  const double pathIr = irCube.weighted / irCube.energy, pathRef = refCube.weighted / refCube.energy;
  // (The later legs' delay in the cube moves IR's mean path by 1.5 cm, within
  // the reference's noise here: printed, not asserted.)
  std::printf("bounces 2 + 3 with the cube over without: IR %.4f, reference %.4f; mean path with "
              "the cube IR %.4f m, reference %.4f m\n",
              ratioIr, ratioRef, pathIr, pathRef);
  EXPECT_LT(ratioIr, 0.9);
  EXPECT_NEAR(ratioIr, ratioRef, 0.03 * ratioRef);
}

// A later bounce's leg through an absorbing slab region (z in [0.4, 0.6] m)
// between a floor VPL and a ceiling at z = 1: each child on the ceiling is
// its vacuum twin (the same ray: an absorbing region draws nothing) with its
// flux times exp(-sigma_a 0.2 / cos) and its path plus eta (eta_r - 1)
// 0.2 / cos, cos the ray's angle to the slab's normal (closed form, per child).
TEST(ScatteringRegionsTest, ALaterBouncesLegThroughASlabIsAttenuatedAndDelayed) {
  scene::Scene scene = test::makePlane(100.0f, glm::vec3(0.5f));  // the floor, z = 0
  test::addQuad(scene, glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.0f, 0.0f, -1.0f), 100.0f,
                glm::vec3(0.5f));
  addBox(scene, "slab", {-50.0f, -50.0f, 0.4f}, {50.0f, 50.0f, 0.6f});
  scene.regions.push_back(*scene::takeRegionMesh(scene, "slab"));
  const rays::RayScene rays(scene, 1);
  capture::RegionMedium slab{"slab", {}, 1.5};
  slab.medium.sigma_a_per_m = {2.0f, 1.0f, 0.5f};
  const double axisIndex = 1.2;  // the time axis' index: the slab adds eta_r / eta_axis - 1
  const capture::MediumRegions regions({slab}, scene, axisIndex);
  ir::Vpl parent;
  parent.positionPath = glm::vec4(0.1f, -0.2f, 0.0f, 2.0f);
  parent.normal = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f);
  parent.flux = glm::vec4(glm::vec3(0.3f), 0.0f);
  parent.vertex = physics::scatterVertex(physics::VERTEX_LAMBERTIAN, glm::vec3(0.5f), 0.0f, 1.0f);
  ir::BounceTracing through;
  through.regions = &regions;
  const std::vector<ir::Vpl> air = ir::traceBounce(rays, {parent}, 256, 2, 7, axisIndex);
  const std::vector<ir::Vpl> inSlab =
      ir::traceBounce(rays, {parent}, 256, 2, 7, axisIndex, through);
  ASSERT_EQ(air.size(), inSlab.size());
  int onCeiling = 0;
  for (std::size_t i = 0; i < air.size(); ++i) {
    ASSERT_EQ(glm::vec3(air[i].positionPath), glm::vec3(inSlab[i].positionPath));
    // The ray left the floor lifted by the scene's epsilon along its normal:
    // its direction is the hit's from there.
    const glm::dvec3 leg = glm::dvec3(glm::vec3(air[i].positionPath)) -
                           glm::dvec3(glm::vec3(parent.positionPath)) -
                           glm::dvec3(0.0, 0.0, rays.epsilon_m());
    if (std::abs(glm::vec3(air[i].positionPath).z - 1.0f) > 1e-4f) continue;  // not on the ceiling
    ++onCeiling;
    const double inside = 0.2 * glm::length(leg) / leg.z;
    for (int c = 0; c < 3; ++c) {
      const double expected = air[i].flux[c] * std::exp(-slab.medium.sigma_a_per_m[c] * inside);
      EXPECT_NEAR(inSlab[i].flux[c], expected, 1e-5 * expected) << "child " << i;
    }
    const double delay = axisIndex * (1.5 / axisIndex - 1.0) * inside;
    EXPECT_NEAR(inSlab[i].positionPath.w - air[i].positionPath.w, delay, 2e-5) << "child " << i;
  }
  EXPECT_GT(onCeiling, 200);
}

bool sameBytes(const TransientVolume& a, const TransientVolume& b) {
  return a.values().size() == b.values().size() &&
         std::memcmp(a.values().data(), b.values().data(), a.values().size() * sizeof(float)) == 0;
}

// A scattering region's single scattering, an absorbing region's later
// bounces, a scattering region's medium VPLs and later flights: each pixel is
// one thread's, each VPL's legs its own ray's (its own generator).
TEST(ScatteringRegionsTest, RegionsRenderTheSameBytesOnAnyThreadCount) {
  const ScatteringCornerJob s;
  capture::RenderJob bounced = s.job;
  bounced.settings.media.front().medium.sigma_s_per_m = glm::vec3(0.0f);
  bounced.settings.indirect.enabled = true;
  bounced.settings.indirect.bounces = 3;
  bounced.settings.indirect.rsm_resolution = 24;
  // The scattering cube's medium VPLs, their light in the camera rays, a
  // later bounce's free flights.
  capture::RenderJob scattered = s.job;
  scattered.settings.indirect.enabled = true;
  scattered.settings.indirect.bounces = 2;
  scattered.settings.indirect.rsm_resolution = 24;
  scattered.settings.indirect.medium_vpls = 2048;
  const capture::RenderJob* jobs[] = {&s.job, &bounced, &scattered};
  for (const capture::RenderJob* job : jobs) {
    const test::CpuRender one = test::renderOnCpu(*job, {1, true});
    const test::CpuRender three = test::renderOnCpu(*job, {3, true});
    EXPECT_GT(energy(one.volume.direct), 0.0);
    EXPECT_TRUE(sameBytes(one.volume.direct, three.volume.direct));
    EXPECT_TRUE(sameBytes(one.volume.indirect, three.volume.indirect));
  }
}

}  // namespace
}  // namespace tofsim::cpu
