#include "tofsim/pipeline/Capture.h"

#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {

const scene::SceneCamera& findCamera(const config::RunConfig& config, const scene::Scene& scene) {
  const std::string& wanted = config.camera.gltf_camera;
  for (const scene::SceneCamera& c : scene.cameras) {
    if (c.name == wanted) return c;
  }
  if (wanted.find_first_not_of("0123456789") == std::string::npos) {
    const std::size_t index = std::stoul(wanted);
    if (index < scene.cameras.size()) return scene.cameras[index];
  }
  std::string known;
  for (const scene::SceneCamera& c : scene.cameras) known += (known.empty() ? "" : ", ") + c.name;
  throw InputError(FileLoc{config.config_file.string()}, "camera.gltf_camera",
                   "no camera '" + wanted + "' in " + config.scene_file.string() +
                       (known.empty() ? " (it has none)" : " (it has: " + known + ")"));
}

}  // namespace

capture::RenderJob makeRenderJob(const config::RunConfig& config, const scene::Scene& scene) {
  capture::RenderJob job;
  job.scene = &scene;
  job.camera() = config.camera.camera;
  job.settings = config.render;
  job.settings.indirect.trace_threads = config.cpu_threads;
  job.light = config.light.light;
  if (config.rays) {  // the light is not attached (the loader refuses it)
    job.imager = config.rays->imager;
    return job;
  }
  if (!config.camera.gltf_camera.empty()) {
    const scene::SceneCamera& c = findCamera(config, scene);
    job.camera().position_world = c.position_world;
    job.camera().look_at_world = c.position_world + c.forward_world;
    job.camera().up_world = c.up_world;
    job.camera().fov_y_deg = c.fov_y_deg;
  }
  if (config.light.attach_to_camera) {
    const capture::Camera& cam = job.camera();
    const glm::vec3 offset = config.light.offset_camera_m;
    job.light.position_world = cam.position_world + offset.x * cam.right() + offset.y * cam.up() +
                               offset.z * cam.forward();
    job.light.direction_world = cam.forward();
  }
  return job;
}

}  // namespace tofsim::pipeline
