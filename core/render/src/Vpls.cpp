#include "Vpls.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <utility>

#include "GpuScene.h"
#include "SurfaceMaps.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/ir/RsmEdgeTexels.h"
#include "tofsim/ir/RsmTexels.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::render {

namespace {

// One view's RSM at some side, read back: the surface of each texel.
class RsmReadback {
 public:
  RsmReadback(const GpuScene& scene, const glm::mat4& viewProjection, const glm::vec3& light_world,
              int side, bool gltf)
      : side_(side) {
    const std::size_t texels = static_cast<std::size_t>(side) * side;
    SurfaceMaps rsm(side, side, gltf);
    rsm.render(scene, viewProjection, light_world);
    position_.resize(texels * 4), normal_.resize(texels * 4), albedo_.resize(texels * 4);
    rsm.position.download(GL_RGBA, GL_FLOAT, position_.size() * sizeof(float), position_.data());
    rsm.normal.download(GL_RGBA, GL_FLOAT, normal_.size() * sizeof(float), normal_.data());
    rsm.albedo.download(GL_RGBA, GL_FLOAT, albedo_.size() * sizeof(float), albedo_.data());
    if (gltf) {
      metallicRoughness_.resize(texels * 2);
      rsm.metallicRoughness.download(GL_RG, GL_FLOAT, metallicRoughness_.size() * sizeof(float),
                                     metallicRoughness_.data());
    }
  }

  /// Texel (x, y)'s VPL (row 0 at the bottom), or nothing; `materials`: the
  /// vertex table the texels index (ir::materialVertices).
  std::optional<Vpl> vpl(const capture::Light& light, const ir::RsmView& view, int x, int y,
                         double indexOfRefraction,
                         const std::vector<physics::ScatterVertex>& materials) const {
    const std::size_t i = (static_cast<std::size_t>(y) * side_ + x) * 4;
    if (position_[i + 3] == 0.0f) return std::nullopt;
    // Without the metallic-roughness map (a Lambertian render) its texel is 1.
    const bool mr = !metallicRoughness_.empty();
    const auto material = static_cast<std::size_t>(albedo_[i + 3]);
    const ir::RsmTexelSurface surface{
        glm::vec3(position_[i], position_[i + 1], position_[i + 2]),
        glm::vec3(normal_[i], normal_[i + 1], normal_[i + 2]),
        physics::texturedVertex(
            materials.at(material), glm::vec3(albedo_[i], albedo_[i + 1], albedo_[i + 2]),
            mr ? glm::vec2(metallicRoughness_[i / 2], metallicRoughness_[i / 2 + 1])
               : glm::vec2(1.0f))};
    return ir::rsmTexelVpl(light, view, side_, x, y, surface, indexOfRefraction);
  }

 private:
  int side_;
  std::vector<float> position_, normal_, albedo_, metallicRoughness_;
};

}  // namespace

std::vector<Vpl> generateVpls(const GpuScene& scene, const capture::Light& light, int resolution,
                              int edgeSamples, double indexOfRefraction, const glm::vec3& lo,
                              const glm::vec3& hi, int vertexModel,
                              const capture::Medium& medium) {
  const bool gltf = mapsMetallicRoughness(vertexModel);
  const std::vector<physics::ScatterVertex> materials =
      ir::materialVertices(scene.scene(), vertexModel);
  std::vector<Vpl> vpls;
  const glm::vec2 range = depthRange(lo, hi, light.position_world);
  for (const ir::RsmView& v : ir::rsmViews(light)) {
    throwIfInterrupted();
    const glm::mat4 projection = glm::perspective(2.0f * v.halfAngle_rad, 1.0f, range.x, range.y);
    const glm::mat4 viewProjection = projection * v.viewMatrix(light.position_world);
    const RsmReadback rsm(scene, viewProjection, light.position_world, resolution, gltf);
    ir::TexelVpls texels(resolution);
    for (int y = 0; y < resolution; ++y) {
      for (int x = 0; x < resolution; ++x) {
        if (const auto vpl = rsm.vpl(light, v, x, y, indexOfRefraction, materials)) {
          texels.add(static_cast<std::size_t>(y) * resolution + x, *vpl);
        }
      }
    }
    // The edge texels' sub-texels from the view rasterised n times finer:
    // the same frustum, so its texel centres are the CPU's sub-texel rays.
    const ir::SubTexelSource subTexels = [&](const std::vector<uint8_t>& edges, int n) {
      throwIfInterrupted();
      const RsmReadback fine(scene, viewProjection, light.position_world, n * resolution, gltf);
      std::vector<std::optional<Vpl>> subs;
      for (std::size_t t = 0; t < edges.size(); ++t) {
        if (!edges[t]) continue;
        const int x = static_cast<int>(t % resolution), y = static_cast<int>(t / resolution);
        for (int j = 0; j < n; ++j) {
          for (int i = 0; i < n; ++i) {
            subs.push_back(
                fine.vpl(light, v, x * n + i, y * n + j, indexOfRefraction, materials));
          }
        }
      }
      return subs;
    };
    const std::vector<Vpl> ofView = ir::rsmViewVpls(
        std::move(texels), resolution, ir::rsmEdgeSamples(edgeSamples, resolution), subTexels);
    vpls.insert(vpls.end(), ofView.begin(), ofView.end());
  }
  ir::attenuateLightLegs(vpls, medium, indexOfRefraction);
  return vpls;
}

}  // namespace tofsim::render
