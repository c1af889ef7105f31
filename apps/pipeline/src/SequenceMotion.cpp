#include "SequenceMotion.h"

#include <limits>
#include <optional>

#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/Capture.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {

constexpr float kNone = std::numeric_limits<float>::quiet_NaN();

}  // namespace

MotionFields motionFields(const config::RunConfig& config, const scene::AnimatedScene& animated,
                          scene::Scene& scene, double t0_s, double t1_s) {
  animated.updateScene(scene, t0_s);
  const capture::RenderJob at0 = makeRenderJob(config, scene);
  const capture::Camera* camera0 = capture::cameraOf(at0.imager);
  TOFSIM_CHECK_MSG(camera0 != nullptr, "a capture sequence's imager is a camera");
  const int32_t W = camera0->width, H = camera0->height;
  std::vector<std::optional<rays::SurfaceHit>> hits(static_cast<std::size_t>(W) * H);
  {
    const rays::RayScene rayScene(scene, config.cpu_threads);
    const capture::PrimaryRays primary(at0.imager);
    for (int32_t y = 0; y < H; ++y) {
      for (int32_t x = 0; x < W; ++x) {
        const capture::PrimaryRay ray = primary.ray(x, y);
        hits[static_cast<std::size_t>(y) * W + x] = rayScene.intersect(ray.origin, ray.direction);
      }
    }
  }
  animated.updateScene(scene, t1_s);
  const capture::RenderJob at1 = makeRenderJob(config, scene);
  const capture::Camera* camera1 = capture::cameraOf(at1.imager);
  TOFSIM_CHECK(camera1 != nullptr);

  MotionFields m{Image(W, H, 3), Image(W, H, 2)};
  for (int32_t y = 0; y < H; ++y) {
    for (int32_t x = 0; x < W; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * W + x;
      for (int c = 0; c < 3; ++c) m.sceneFlow_m.at(y, x, c) = kNone;
      for (int c = 0; c < 2; ++c) m.opticalFlow_px.at(y, x, c) = kNone;
      if (!hits[i]) continue;
      // The same point on its triangle, where the triangle is at t1
      // (position_world is surfacePoint's at t0).
      const rays::SurfaceHit& hit = *hits[i];
      const glm::vec3 from = hit.position_world;
      const glm::vec3 to = rays::surfacePoint(scene, hit.mesh, hit.triangle, hit.barycentric);
      const glm::vec3 d = to - from;
      for (int c = 0; c < 3; ++c) m.sceneFlow_m.at(y, x, c) = d[c];
      const std::optional<glm::dvec2> p0 = camera0->imagePoint(from);
      const std::optional<glm::dvec2> p1 = camera1->imagePoint(to);
      if (!p0 || !p1) continue;  // behind a camera: no image displacement
      m.opticalFlow_px.at(y, x, 0) = static_cast<float>(p1->x - p0->x);
      m.opticalFlow_px.at(y, x, 1) = static_cast<float>(p1->y - p0->y);
    }
  }
  return m;
}

void writeMotionFields(const std::filesystem::path& dir, const MotionFields& motion,
                       std::vector<std::string>& files) {
  const auto H = static_cast<std::size_t>(motion.sceneFlow_m.height);
  const auto W = static_cast<std::size_t>(motion.sceneFlow_m.width);
  io::writeNpy(dir / "scene_flow.npy", {H, W, 3}, motion.sceneFlow_m.data.data());
  io::writeNpy(dir / "optical_flow.npy", {H, W, 2}, motion.opticalFlow_px.data.data());
  files.push_back("scene_flow.npy");
  files.push_back("optical_flow.npy");
}

}  // namespace tofsim::pipeline
