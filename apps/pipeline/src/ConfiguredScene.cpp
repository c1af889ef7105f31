#include "tofsim/pipeline/ConfiguredScene.h"

#include <stdexcept>
#include <string>

#include "tofsim/config/MaterialDelays.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/ir/VplClasses.h"
#include "tofsim/physics/ResponseClassTable.h"
#include "tofsim/pipeline/NlosScan.h"
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
  ir::MaterialResponses responses = ir::materialResponses(scene);
  if (responses.kernels.empty()) return;
  const int32_t bounces = config.render.indirect.bounces;
  // An NLOS scan's laser spot stands on its relay wall (NlosScanGeometry::capture).
  capture::Light light;
  if (config.nlos) light.surface_material = relayWallMaterial(scene, config.nlos->relay_wall);
  const uint32_t start = ir::lightResponse(responses, light);
  try {
    // The table the driver builds (IrRenderer), thrown away.
    (void)ir::responseClasses(std::move(responses.kernels), config.render.indirect, start);
  } catch (const std::invalid_argument& e) {
    std::string delayed;
    for (const scene::Material& m : scene.materials) {
      if (m.scatteringDelay) delayed += (delayed.empty() ? "" : ", ") + m.name;
    }
    throw InputError(config.materials_at, "render.indirect.bounces",
                     std::string(e.what()) + " (render.indirect.bounces: " +
                         std::to_string(bounces) + ", plus the surface the camera sees" +
                         (start != 0 ? " and the relay wall's laser spot" : "") + "; delayed " +
                         "materials: " + delayed + "): lower render.indirect.bounces, or give " +
                         "materials equal scattering delays (they share a kernel)");
  }
}

}  // namespace tofsim::pipeline
