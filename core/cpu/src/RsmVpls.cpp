#include "RsmVpls.h"

#include <optional>
#include <utility>

#include "LitBounds.h"
#include "ParallelFor.h"
#include "tofsim/ir/HitVertex.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/ir/RsmEdgeTexels.h"
#include "tofsim/ir/RsmTexels.h"
#include "tofsim/ir/VplClasses.h"

namespace tofsim::cpu {

namespace {

// The VPL of texel (x, y) of a view (row 0 at the bottom, as GL stores it), or
// nothing when the texel sees no lit surface: a ray where the GL rasterises.
std::optional<ir::Vpl> texelVpl(const rays::RayScene& scene, const capture::Light& light,
                                const ir::RsmView& v, int resolution, int x, int y, double eta,
                                const std::vector<physics::ScatterVertex>& materials,
                                const std::optional<scene::Bounds>& lit) {
  const glm::vec3 direction = ir::rsmTexelDirection(v, resolution, x, y);
  // A Lambertian light's side views look half behind it: no ray there.
  if (light.type == capture::Light::Type::Lambertian && light.angularProfile(direction) <= 0.0f) {
    return std::nullopt;
  }
  if (lit && !rayMeetsBox(light.position_world, direction, *lit)) return std::nullopt;
  const auto hit = scene.intersect(light.position_world, direction);
  if (!hit) return std::nullopt;
  return ir::rsmTexelVpl(light, v, resolution, x, y,
                         {hit->position_world, hit->normal_world, ir::hitVertex(*hit, materials)},
                         eta);
}

}  // namespace

std::vector<ir::Vpl> traceRsmVpls(const rays::RayScene& scene, const capture::Light& light,
                                  int resolution, int edgeSamples, double indexOfRefraction,
                                  int vertexModel, int threads,
                                  const std::optional<scene::Bounds>& lit,
                                  const physics::ResponseClassTable* classes,
                                  const capture::Medium& medium) {
  const std::vector<physics::ScatterVertex> materials =
      ir::materialVertices(scene.scene(), vertexModel);
  const auto trace = [&](const ir::RsmView& view, int side, int x, int y) {
    return texelVpl(scene, light, view, side, x, y, indexOfRefraction, materials, lit);
  };
  std::vector<ir::Vpl> vpls;
  for (const ir::RsmView& view : ir::rsmViews(light)) {
    // Rows in parallel, then gathered in texel order.
    std::vector<std::vector<std::pair<int, ir::Vpl>>> rows(static_cast<std::size_t>(resolution));
    parallelFor(rows.size(), threads, [&](std::size_t row) {
      for (int x = 0; x < resolution; ++x) {
        if (const auto vpl = trace(view, resolution, x, static_cast<int>(row))) {
          rows[row].emplace_back(x, *vpl);
        }
      }
    });
    ir::TexelVpls texels(resolution);
    for (std::size_t row = 0; row < rows.size(); ++row) {
      for (const auto& [x, vpl] : rows[row]) texels.add(row * resolution + x, vpl);
      std::vector<std::pair<int, ir::Vpl>>().swap(rows[row]);
    }
    // Rays for the edge texels' sub-texels only, an edge texel per task.
    const ir::SubTexelSource subTexels = [&](const std::vector<uint8_t>& edges, int n) {
      std::vector<std::size_t> edgeTexels;
      for (std::size_t i = 0; i < edges.size(); ++i) {
        if (edges[i]) edgeTexels.push_back(i);
      }
      const std::size_t perTexel = static_cast<std::size_t>(n) * n;
      std::vector<std::optional<ir::Vpl>> subs(edgeTexels.size() * perTexel);
      parallelFor(edgeTexels.size(), threads, [&](std::size_t e) {
        const int x = static_cast<int>(edgeTexels[e] % resolution);
        const int y = static_cast<int>(edgeTexels[e] / resolution);
        for (int j = 0; j < n; ++j) {
          for (int i = 0; i < n; ++i) {
            subs[e * perTexel + j * n + i] = trace(view, n * resolution, x * n + i, y * n + j);
          }
        }
      });
      return subs;
    };
    const std::vector<ir::Vpl> ofView = ir::rsmViewVpls(
        std::move(texels), resolution, ir::rsmEdgeSamples(edgeSamples, resolution), subTexels);
    vpls.insert(vpls.end(), ofView.begin(), ofView.end());
  }
  // After the edge texels' merges, which sum their members' fluxes.
  ir::attenuateLightLegs(vpls, medium, indexOfRefraction);
  if (classes != nullptr) ir::setFirstBounceClasses(vpls, *classes);
  return vpls;
}

}  // namespace tofsim::cpu
