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

glm::vec3 pointOn(const scene::Scene& scene, const rays::SurfaceHit& hit) {
  const scene::Mesh& mesh = scene.meshes.at(hit.mesh);
  const uint32_t* tri = &mesh.indices.at(static_cast<std::size_t>(hit.triangle) * 3);
  const float u = hit.barycentric.x, v = hit.barycentric.y, w = 1.0f - u - v;
  return w * mesh.positions_world[tri[0]] + u * mesh.positions_world[tri[1]] +
         v * mesh.positions_world[tri[2]];
}

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
  std::vector<glm::vec3> from(hits.size());
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (hits[i]) from[i] = pointOn(scene, *hits[i]);  // as the triangle gives it, as at t1
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
      const glm::vec3 to = pointOn(scene, *hits[i]);
      const glm::vec3 d = to - from[i];
      for (int c = 0; c < 3; ++c) m.sceneFlow_m.at(y, x, c) = d[c];
      const std::optional<glm::dvec2> p0 = camera0->imagePoint(from[i]);
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
