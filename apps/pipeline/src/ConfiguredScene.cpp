#include "tofsim/pipeline/ConfiguredScene.h"

#include <stdexcept>
#include <string>

#include "tofsim/config/MaterialDelays.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/ir/VplClasses.h"
#include "tofsim/physics/ResponseClassTable.h"
#include "tofsim/pipeline/NlosScan.h"
#include "tofsim/render/GlRegionLimits.h"
#include "tofsim/scene/RegionMeshes.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

scene::Scene loadConfiguredScene(const config::RunConfig& config, scene::LoadReport* report) {
  scene::LoadReport own;
  scene::LoadReport& r = report ? *report : own;
  scene::Scene scene = scene::loadGltf(config.scene_file, &r);
  configureScene(config, scene, r);
  return scene;
}

namespace {

bool boxesOverlap(const scene::Bounds& a, const scene::Bounds& b) {
  return glm::all(glm::lessThan(a.min, b.max)) && glm::all(glm::lessThan(b.min, a.max));
}

// On GL every leg walks the regions' triangles in the shaders (their loop
// trips bounded: render/GlRegionLimits.h): more are refused at the region
// that passes the limit. With render.backend: auto the backend refuses them
// if it is GL.
void refuseRegionsTooLargeForGl(const config::RunConfig& config, const scene::Scene& scene,
                                const FileLoc& at, const std::string& key) {
  if (config.renderer != config::RendererKind::InstantRadiosity ||
      config.backend != config::IrBackendKind::Gl) {
    return;
  }
  std::size_t triangles = 0;
  for (const scene::RegionMesh& r : scene.regions) triangles += r.triangles_world.size() / 3;
  const std::size_t limit = render::glRegionTriangleLimit(config.render.pixel_samples);
  if (triangles <= limit) return;
  throw InputError(at, key,
                   "the media's regions have " + std::to_string(triangles) +
                       " triangles with the mesh '" + scene.regions.back().name +
                       "': the GL backend takes at most " + std::to_string(limit) +
                       " with render.pixel_samples " + std::to_string(config.render.pixel_samples) +
                       " (each leg walks them all in the shaders): set `render.backend: cpu`, "
                       "fewer pixel samples, or a mesh of fewer triangles");
}

}  // namespace

void takeMediumRegions(const config::RunConfig& config, scene::Scene& scene) {
  scene.regions.clear();
  for (std::size_t i = 0; i < config.render.media.size(); ++i) {
    const std::string& name = config.render.media[i].region;
    const FileLoc& at = config.media[i].region_at;
    const std::string key = "media[" + std::to_string(i) + "].region";
    std::optional<scene::RegionMesh> region = scene::takeRegionMesh(scene, name);
    if (!region) {
      throw InputError(at, key,
                       "the scene (" + config.scene_file.string() + ") has no mesh or node named '" +
                           name + "'");
    }
    const std::string problem = scene::regionMeshProblem(*region);
    if (!problem.empty()) {
      throw InputError(at, key,
                       "the mesh '" + name + "' " + problem +
                           ": a medium's region must be a closed, consistently wound mesh");
    }
    // Regions neither overlap nor nest (a segment's passage is a sum over
    // them): their boxes must be apart, which is stricter but checkable.
    for (std::size_t j = 0; j < scene.regions.size(); ++j) {
      if (boxesOverlap(scene::regionBounds(*region), scene::regionBounds(scene.regions[j]))) {
        throw InputError(at, key,
                         "the region '" + name + "' overlaps the region '" + scene.regions[j].name +
                             "' (" + config.media[j].region_at.toString() +
                             "): media's regions must not overlap nor nest (their bounding "
                             "boxes must be apart)");
      }
    }
    scene.regions.push_back(std::move(*region));
    refuseRegionsTooLargeForGl(config, scene, at, key);
  }
}

void configureScene(const config::RunConfig& config, scene::Scene& scene,
                    const scene::LoadReport& report) {
  config::applyMaterialDelays(config, scene, report.materialExtras);
  takeMediumRegions(config, scene);
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
