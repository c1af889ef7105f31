#pragma once
// Render jobs shared by the tests and benchmarks: the closed-form plane, a
// floor + wall corner for indirect light, and the Cornell box seen by a ToF
// camera with its light at the lens.

#include "support/AnalyticScenes.h"
#include "tofsim/capture/RenderJob.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::test {

/// A 6 m plane at z = 0 seen by a camera 1.5 m away with a point light at the
/// camera (same as tests/render/DirectRenderGLTest.cpp).
struct PlaneJob {
  scene::Scene scene = makePlane(6.0f, glm::vec3(0.5f, 0.4f, 0.3f));
  capture::RenderJob job;
  PlaneJob() {
    job.scene = &scene;
    job.camera().position_world = {0.0f, 0.0f, 1.5f};
    job.camera().look_at_world = {0.2f, 0.1f, 0.0f};
    job.camera().fov_y_deg = 60.0f;
    job.camera().width = 40;
    job.camera().height = 30;
    job.light.position_world = job.camera().position_world;
    job.light.intensity_W_per_sr = glm::vec3(2.0f, 1.0f, 0.5f);
    job.settings.time = TimeAxis{2.5 / kSpeedOfLight_m_per_s, 0.002 / kSpeedOfLight_m_per_s, 1200};
  }
};

/// A 2 m floor (y = 0, facing +y) meeting a 2 m wall (z = -1, facing +z): the
/// smallest scene with one-bounce indirect light.
struct CornerJob {
  scene::Scene scene;
  capture::RenderJob job;
  explicit CornerJob(int32_t side = 16) {
    addQuad(scene, glm::vec3(0.0f, 0.0f, 0.0f), glm::vec3(0, 1, 0), 2.0f,
            glm::vec3(0.7f, 0.6f, 0.5f));
    addQuad(scene, glm::vec3(0.0f, 1.0f, -1.0f), glm::vec3(0, 0, 1), 2.0f,
            glm::vec3(0.3f, 0.8f, 0.4f));
    job.scene = &scene;
    job.camera().position_world = {0.3f, 1.2f, 2.0f};
    job.camera().look_at_world = {0.0f, 0.4f, -0.5f};
    job.camera().fov_y_deg = 55.0f;
    job.camera().width = side;
    job.camera().height = side;
    job.light.position_world = {0.5f, 1.5f, 0.5f};
    job.light.intensity_W_per_sr = glm::vec3(3.0f);
    job.settings.time = TimeAxis{0.0, 0.01 / kSpeedOfLight_m_per_s, 1000};
  }
};

/// The corner with a glossy floor (a rough metal) and a glossy dielectric
/// wall, its materials used (render.materials: gltf).
inline CornerJob glossyCorner(int32_t side) {
  CornerJob s(side);
  s.scene.materials.at(0).metallic = 0.8f;
  s.scene.materials.at(0).roughness = 0.35f;
  s.scene.materials.at(1).roughness = 0.5f;
  s.job.settings.materials = capture::MaterialModel::Gltf;
  return s;
}

/// The published Cornell camera (0.278, 0.273, -0.8) m, 39.3 degrees, with a
/// 28-degree spot light 5 cm to its right aimed into the box, as a ToF
/// illuminator. `bins` of `binWidth_m` optical path from 1.5 m.
inline capture::RenderJob cornellBoxJob(const scene::Scene& scene, int32_t resolution, int32_t bins,
                                        double binWidth_m) {
  capture::RenderJob job;
  job.scene = &scene;
  job.camera().position_world = {0.278f, 0.273f, -0.8f};
  job.camera().look_at_world = {0.278f, 0.273f, 0.0f};
  job.camera().fov_y_deg = 39.3f;
  job.camera().width = job.camera().height = resolution;
  job.light.type = capture::Light::Type::Spot;
  job.light.position_world = {0.328f, 0.273f, -0.8f};
  job.light.direction_world = {0.0f, 0.0f, 1.0f};
  job.light.cone_half_angle_deg = 28.0f;
  job.settings.time =
      TimeAxis{1.5 / kSpeedOfLight_m_per_s, binWidth_m / kSpeedOfLight_m_per_s, bins};
  return job;
}

}  // namespace tofsim::test
