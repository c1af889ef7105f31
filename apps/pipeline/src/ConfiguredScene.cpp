#include "tofsim/pipeline/ConfiguredScene.h"

#include <stdexcept>
#include <string>

#include "tofsim/config/MaterialDelays.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/ir/VplClasses.h"
#include "tofsim/physics/ResponseClassTable.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

scene::Scene loadConfiguredScene(const config::RunConfig& config, scene::LoadReport* report) {
  scene::LoadReport own;
  scene::LoadReport& r = report ? *report : own;
  scene::Scene scene = scene::loadGltf(config.scene_file, &r);
  configureScene(config, scene, r);
  return scene;
}

void configureScene(const config::RunConfig& config, scene::Scene& scene,
                    const scene::LoadReport& report) {
  config::applyMaterialDelays(config, scene, report.materialExtras);
  checkResponseClasses(config, scene);
}

void checkResponseClasses(const config::RunConfig& config, const scene::Scene& scene) {
  if (config.renderer != config::RendererKind::InstantRadiosity) return;
  const ir::MaterialResponses responses = ir::materialResponses(scene);
  if (responses.kernels.empty()) return;
  const int32_t bounces = config.render.indirect.bounces;
  try {
    // The table the driver builds (IrRenderer), thrown away.
    (void)physics::ResponseClassTable::build(responses.kernels,
                                             ir::responseDepth(config.render.indirect));
  } catch (const std::invalid_argument& e) {
    std::string delayed;
    for (const scene::Material& m : scene.materials) {
      if (m.scatteringDelay) delayed += (delayed.empty() ? "" : ", ") + m.name;
    }
    throw InputError(config.materials_at, "render.indirect.bounces",
                     std::string(e.what()) + " (render.indirect.bounces: " +
                         std::to_string(bounces) + ", plus the surface the camera sees; delayed " +
                         "materials: " + delayed + "): lower render.indirect.bounces, or give " +
                         "materials equal scattering delays (they share a kernel)");
  }
}

}  // namespace tofsim::pipeline
