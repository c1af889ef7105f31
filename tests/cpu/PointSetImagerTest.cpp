// The point-set imager (capture::PointSetImager) on the CPU backend: a relay
// wall's grid of points seen from a sensor origin, lit by a point light.
// Direct light at each point against its closed form (radiance and the bin
// of its optical path, with and without the last leg), the same light as a
// pinhole sees at the same surface points, and the grid generator's errors.

#include <gtest/gtest.h>

#include <cmath>

#include "support/AnalyticScenes.h"
#include "support/CpuRender.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/util/Error.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::cpu {
namespace {

constexpr float kPi = 3.14159265358979f;

// A 2 m wall at z = 0 facing +z ("quad0"), its 8 x 6 grid seen from a sensor
// at `origin`, a point light at l, direct light only, point samples.
struct RelayWall {
  scene::Scene scene;
  capture::RenderJob job;
  glm::vec3 albedo{0.6f, 0.5f, 0.4f};
  glm::vec3 origin{-0.3f, 0.2f, 1.5f};

  explicit RelayWall(bool lastLegCounts = true) {
    test::addQuad(scene, glm::vec3(0.0f), glm::vec3(0, 0, 1), 2.0f, albedo);
    job.scene = &scene;
    job.imager = capture::gridOnPlanarMesh(scene, "quad0", 8, 6, origin, lastLegCounts);
    job.light.position_world = {0.2f, 0.1f, 1.0f};
    job.light.intensity_W_per_sr = glm::vec3(2.0f, 1.0f, 0.5f);
    job.settings.indirect.enabled = false;
    job.settings.pixel_footprint = false;
    job.settings.time = TimeAxis{0.0, 0.005 / kSpeedOfLight_m_per_s, 1000};
  }
  const capture::PointSetImager& grid() const {
    return std::get<capture::PointSetImager>(job.imager);
  }
};

// Each point's direct light is albedo / pi * I cos / r^2 and lands in the bin
// of |l - x| (+ |x - origin| when the last leg counts), nowhere else.
void expectClosedForm(const RelayWall& wall, bool lastLegCounts) {
  const test::CpuRender render = test::renderOnCpu(wall.job);
  const TransientVolume volume = render.volume.total();
  const TimeAxis& axis = wall.job.settings.time;
  const capture::PointSetImager& grid = wall.grid();
  for (int32_t y = 0; y < grid.height; ++y) {
    for (int32_t x = 0; x < grid.width; ++x) {
      const glm::vec3 p = grid.points_world[static_cast<std::size_t>(y) * grid.width + x];
      const glm::vec3 toLight = wall.job.light.position_world - p;
      const float r = glm::length(toLight);
      const float cosX = toLight.z / r;
      const double path = r + (lastLegCounts ? glm::length(wall.origin - p) : 0.0f);
      const int bin = axis.binOf(path / kSpeedOfLight_m_per_s);
      for (int c = 0; c < 3; ++c) {
        const double expected =
            wall.albedo[c] / kPi * wall.job.light.intensity_W_per_sr[c] * cosX / (r * r);
        double near = 0.0, all = 0.0;
        for (int t = 0; t < axis.bins; ++t) {
          all += volume.at(y, x, t, c);
          if (std::abs(t - bin) <= 1) near += volume.at(y, x, t, c);  // float rounding of the hit
        }
        EXPECT_NEAR(near, expected, 1e-4 * expected) << "point " << x << ", " << y;
        EXPECT_NEAR(all, near, 1e-9) << "light outside its bin at point " << x << ", " << y;
      }
      EXPECT_NEAR(render.result.depth_m.at(y, x, 0), glm::length(wall.origin - p), 1e-4);
    }
  }
}

TEST(PointSetImagerTest, RelayWallPointsGetTheClosedFormDirectLightInTheirBin) {
  const RelayWall wall;
  expectClosedForm(wall, true);
}

TEST(PointSetImagerTest, WithoutTheLastLegTheArrivalIsTimedAtThePoint) {
  const RelayWall wall(false);
  expectClosedForm(wall, false);
}

// The grid covers the quad: cell centres 2 m / 8 and 2 m / 6 apart, steps
// along u and down v, the first point in the top-left cell.
TEST(PointSetImagerTest, TheGridLaysCellCentresOnThePlanarMesh) {
  const RelayWall wall;
  const capture::PointSetImager& g = wall.grid();
  ASSERT_EQ(g.points_world.size(), 48u);
  EXPECT_NEAR(glm::length(g.step_u_world), 0.25f, 1e-6f);
  EXPECT_NEAR(glm::length(g.step_v_world), 2.0f / 6.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(g.step_u_world, g.step_v_world), 0.0f, 1e-6f);
  for (const glm::vec3& p : g.points_world) {
    EXPECT_NEAR(p.z, 0.0f, 1e-6f);
    EXPECT_LT(std::fabs(p.x), 1.0f);
    EXPECT_LT(std::fabs(p.y), 1.0f);
  }
  const glm::vec3 next = g.points_world[1] - g.points_world[0];
  const glm::vec3 below = g.points_world[8] - g.points_world[0];
  EXPECT_NEAR(glm::length(next - g.step_u_world), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(below - g.step_v_world), 0.0f, 1e-5f);
}

// A point set through the pinhole's own surface points gathers the pinhole's
// light (the same gather; point samples, so only the points matter).
TEST(PointSetImagerTest, PointsAtAPinholesHitsSeeThePinholesLight) {
  RelayWall wall;
  capture::Camera camera;
  camera.position_world = wall.origin;
  camera.look_at_world = {0.1f, 0.0f, 0.0f};
  camera.fov_y_deg = 30.0f;
  camera.width = 10;
  camera.height = 8;
  wall.job.imager = camera;
  const test::CpuRender pinhole = test::renderOnCpu(wall.job);
  capture::PointSetImager points;
  points.width = camera.width;
  points.height = camera.height;
  points.origin_world = camera.position_world;
  for (int32_t y = 0; y < camera.height; ++y) {
    for (int32_t x = 0; x < camera.width; ++x) {
      const float d = pinhole.result.depth_m.at(y, x, 0);
      ASSERT_GT(d, 0.0f) << "every pixel sees the wall";
      points.points_world.push_back(camera.position_world + d * camera.pixelDirection(x, y));
    }
  }
  wall.job.imager = points;
  const test::CpuRender onPoints = test::renderOnCpu(wall.job);
  const Image a = steadyImage(pinhole.volume.total());
  const Image b = steadyImage(onPoints.volume.total());
  for (int32_t y = 0; y < camera.height; ++y) {
    for (int32_t x = 0; x < camera.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(b.at(y, x, c), a.at(y, x, c), 1e-4 * a.at(y, x, c)) << x << ", " << y;
      }
    }
  }
}

TEST(PointSetImagerTest, TheGridNamesAMissingOrCurvedMesh) {
  scene::Scene scene;
  test::addQuad(scene, glm::vec3(0.0f), glm::vec3(0, 0, 1), 1.0f, glm::vec3(0.5f));
  try {
    capture::gridOnPlanarMesh(scene, "wall", 4, 4, glm::vec3(0, 0, 1));
    FAIL() << "a missing mesh must be an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'wall'"), std::string::npos) << e.what();
  }
  scene.meshes[0].positions_world[0].z += 0.1f;  // bend the quad
  try {
    capture::gridOnPlanarMesh(scene, "quad0", 4, 4, glm::vec3(0, 0, 1));
    FAIL() << "a curved mesh must be an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not planar"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tofsim::cpu
