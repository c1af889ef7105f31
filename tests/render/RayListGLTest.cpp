// The ray-list imager (capture::RayListImager): pixels that are the user's
// own rays, each with its own origin, on both IR backends. Direct light of
// rays from several origins onto a lit wall against its closed form (the
// arrival in the bin of |l - x| + |x - o|, the 1/r^2 falloff), with and
// without the last leg; a pinhole's pixel-centre rays as a ray list give the
// pinhole's volume; GL equals CPU; the reference path tracer agrees.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "support/AnalyticScenes.h"
#include "support/TestBackends.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::render {
namespace {

using capture::RenderJob;
using capture::VolumeCollector;
constexpr float kPi = 3.14159265358979f;

// A 2 m wall at z = 0 facing +z, lit by a point light, seen by 6 rays from
// 3 origins, each aimed at its own wall point.
struct RayWall {
  scene::Scene scene;
  RenderJob job;
  glm::vec3 albedo{0.6f, 0.5f, 0.4f};
  std::vector<glm::vec3> targets;

  explicit RayWall(bool lastLegCounts = true) {
    test::addQuad(scene, glm::vec3(0.0f), glm::vec3(0, 0, 1), 2.0f, albedo);
    job.scene = &scene;
    const glm::vec3 origins[3] = {{-0.3f, 0.2f, 1.5f}, {0.5f, -0.4f, 0.8f}, {0.0f, 0.6f, 2.5f}};
    capture::RayListImager rays;
    rays.width = 6;
    rays.last_leg_counts = lastLegCounts;
    for (int i = 0; i < 6; ++i) {
      const glm::vec3 target(-0.7f + 0.25f * i, 0.5f - 0.2f * i, 0.0f);
      const glm::vec3 o = origins[i % 3];
      targets.push_back(target);
      rays.rays.push_back({o, glm::normalize(target - o)});
    }
    job.imager = rays;
    job.light.position_world = {0.2f, 0.1f, 1.0f};
    job.light.intensity_W_per_sr = glm::vec3(2.0f, 1.0f, 0.5f);
    job.settings.indirect.enabled = false;
    job.settings.pixel_footprint = false;
    job.settings.time = TimeAxis{0.0, 0.005 / kSpeedOfLight_m_per_s, 1200};
  }
  const capture::RayListImager& rays() const {
    return std::get<capture::RayListImager>(job.imager);
  }
};

VolumeCollector renderOn(test::TestBackend backend, const RenderJob& job) {
  VolumeCollector out(capture::imageWidth(job.imager), capture::imageHeight(job.imager),
                      job.settings.time, 3);
  test::makeTestRenderer(backend)->render(job, out);
  return out;
}

class RayListTest : public test::BackendTest {
 protected:
  // Each ray's direct light is albedo / pi * I cos / r^2, in the bin of
  // |l - x| (+ |x - o| when the last leg counts) and nowhere else.
  void expectClosedForm(bool lastLegCounts) const {
    const RayWall wall(lastLegCounts);
    const VolumeCollector out = renderOn(GetParam(), wall.job);
    const TransientVolume volume = out.total();
    const TimeAxis& axis = wall.job.settings.time;
    for (int32_t x = 0; x < 6; ++x) {
      const glm::vec3 p = wall.targets[x];
      const glm::vec3 o = wall.rays().rays[x].origin;
      const glm::vec3 toLight = wall.job.light.position_world - p;
      const float r = glm::length(toLight);
      const double path = r + (lastLegCounts ? glm::length(o - p) : 0.0f);
      const int bin = axis.binOf(path / kSpeedOfLight_m_per_s);
      for (int c = 0; c < 3; ++c) {
        const double expected =
            wall.albedo[c] / kPi * wall.job.light.intensity_W_per_sr[c] * (toLight.z / r) / (r * r);
        double near = 0.0, all = 0.0;
        for (int t = 0; t < axis.bins; ++t) {
          all += volume.at(0, x, t, c);
          if (std::abs(t - bin) <= 1) near += volume.at(0, x, t, c);
        }
        EXPECT_NEAR(near, expected, 1e-4 * expected) << "ray " << x;
        EXPECT_NEAR(all, near, 1e-9) << "light outside its bin, ray " << x;
      }
    }
  }
};

TEST_P(RayListTest, RaysFromTheirOwnOriginsArriveAfterLightToHitPlusHitToOrigin) {
  expectClosedForm(true);
}

TEST_P(RayListTest, WithoutTheLastLegTheArrivalIsTimedAtTheHit) { expectClosedForm(false); }

// A pinhole's pixel-centre rays as a ray list: the pinhole's volume (the
// CPU's bit for bit; GL's rasterized G-buffer to float rounding).
TEST_P(RayListTest, APinholesCentreRaysGiveThePinholesLight) {
  RayWall wall;
  capture::Camera camera;
  camera.position_world = {-0.3f, 0.2f, 1.5f};
  camera.look_at_world = {0.1f, 0.0f, 0.0f};
  camera.fov_y_deg = 30.0f;
  camera.width = 10;
  camera.height = 8;
  wall.job.imager = camera;
  const VolumeCollector pinhole = renderOn(GetParam(), wall.job);
  capture::RayListImager rays;
  rays.width = camera.width;
  rays.height = camera.height;
  const capture::Imager asImager = camera;
  const capture::PrimaryRays centre(asImager);
  for (int32_t y = 0; y < camera.height; ++y) {
    for (int32_t x = 0; x < camera.width; ++x) rays.rays.push_back(centre.ray(x, y));
  }
  wall.job.imager = rays;
  const VolumeCollector onRays = renderOn(GetParam(), wall.job);
  const TransientVolume a = pinhole.total(), b = onRays.total();
  ASSERT_EQ(a.size(), b.size());
  if (GetParam() == test::TestBackend::Cpu) {
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
    return;
  }
  const Image sa = steadyImage(a), sb = steadyImage(b);
  for (std::size_t i = 0; i < sa.data.size(); ++i) {
    EXPECT_NEAR(sb.data[i], sa.data[i], 1e-4 * sa.data[i] + 1e-9) << i;
  }
}

TOFSIM_ON_BOTH_BACKENDS(RayListTest);

// Each ray's light per channel (summed over time) and its peak bin.
struct RayLight {
  double sum = 0.0;
  int peak = 0;
};
RayLight rayLight(const TransientVolume& v, int32_t x, int c) {
  RayLight out;
  for (int t = 0; t < v.bins(); ++t) {
    out.sum += v.at(0, x, t, c);
    if (v.at(0, x, t, c) > v.at(0, x, out.peak, c)) out.peak = t;
  }
  return out;
}

// GL gathers each sample's own camera end (camera_end.glsl) as the CPU
// does: the same light in the same bins, directly and after a bounce off a
// second wall (whose path also ends at each ray's origin).
TEST(RayListGLTest, GlEqualsCpuDirectAndIndirect) {
  RayWall wall;
  test::addQuad(wall.scene, glm::vec3(0.0f, -1.0f, 1.0f), glm::vec3(0, 1, 0), 2.0f,
                glm::vec3(0.7f));
  wall.job.settings.indirect.enabled = true;
  wall.job.settings.indirect.rsm_resolution = 8;
  const VolumeCollector gl = renderOn(test::TestBackend::Gl, wall.job);
  const VolumeCollector cpu = renderOn(test::TestBackend::Cpu, wall.job);
  for (int32_t x = 0; x < 6; ++x) {
    for (int c = 0; c < 3; ++c) {
      const RayLight g = rayLight(gl.direct, x, c), k = rayLight(cpu.direct, x, c);
      EXPECT_GT(k.sum, 0.0);
      EXPECT_NEAR(g.sum, k.sum, 1e-4 * k.sum) << "direct, ray " << x;
      EXPECT_LE(std::abs(g.peak - k.peak), 1) << "direct, ray " << x;
      const RayLight gi = rayLight(gl.indirect, x, c), ki = rayLight(cpu.indirect, x, c);
      EXPECT_GT(ki.sum, 0.0);
      EXPECT_NEAR(gi.sum, ki.sum, 3e-3 * ki.sum) << "indirect, ray " << x;
    }
  }
}

// The reference path tracer times and weighs each ray's light alike.
TEST(RayListGLTest, TheReferenceAgreesOnDirectLight) {
  const RayWall wall;
  reference::ReferenceSettings options;
  options.bounces = 1;
  options.samples_per_pixel = 1;
  options.threads = 1;
  VolumeCollector ref(6, 1, wall.job.settings.time, 3);
  reference::ReferenceRenderer(options).render(wall.job, ref);
  const TransientVolume a = ref.total();
  const TransientVolume b = renderOn(test::TestBackend::Cpu, wall.job).total();
  ASSERT_EQ(a.size(), b.size());
  // Each ray's light, and its bin (a path within float rounding of a bin
  // edge may land on either side).
  for (int32_t x = 0; x < 6; ++x) {
    for (int c = 0; c < 3; ++c) {
      double sumA = 0.0, sumB = 0.0;
      int peakA = 0, peakB = 0;
      for (int t = 0; t < a.bins(); ++t) {
        sumA += a.at(0, x, t, c);
        sumB += b.at(0, x, t, c);
        if (a.at(0, x, t, c) > a.at(0, x, peakA, c)) peakA = t;
        if (b.at(0, x, t, c) > b.at(0, x, peakB, c)) peakB = t;
      }
      EXPECT_GT(sumB, 0.0);
      EXPECT_NEAR(sumA, sumB, 1e-5 * sumB) << "ray " << x;
      EXPECT_LE(std::abs(peakA - peakB), 1) << "ray " << x;
    }
  }
}

}  // namespace
}  // namespace tofsim::render
