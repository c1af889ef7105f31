#include "tofsim/pipeline/ValidateRun.h"

#include "tofsim/imaging/Video.h"
#include "tofsim/pipeline/ConfiguredScene.h"
#include "tofsim/pipeline/NlosScan.h"
#include "tofsim/pipeline/OutputEstimate.h"
#include "tofsim/pipeline/RenderCapture.h"
#include "tofsim/scene/AnimatedScene.h"

namespace tofsim::pipeline {

void validateRun(const config::RunConfig& config) {
  checkRunSizes(config);  // from the config alone: before the scene loads, as render
  // A sequence's scene is read with its animations, as its render reads it
  // first, so that their errors (a keyframe past the scene bound, a zero
  // quaternion) come from `validate` too.
  scene::LoadReport report;
  scene::Scene scene = config.sequence
                           ? scene::AnimatedScene::load(config.scene_file, &report).restScene()
                           : scene::loadGltf(config.scene_file, &report);
  configureScene(config, scene, report);
  if (config.nlos) {
    planNlosScan(config, scene);  // the relay wall and the origins in front of it
    return;
  }
  // A lidar's beams are not a camera's job: its light off the axis is
  // reported by its render (lidar.json's stats, LidarRun.cpp).
  if (config.lidar) return;
  prepareCapture(config, scene, /*notes=*/true);  // the glTF camera, the time axis
  // The MP4 encoder, a module loaded on first use, as render asks for it.
  if (config.output.video || (config.sequence && config.sequence->video)) {
    imaging::requireVideoEncoder();
  }
}

}  // namespace tofsim::pipeline
