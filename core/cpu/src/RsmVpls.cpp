#include "RsmVpls.h"

#include <optional>

#include "LitBounds.h"
#include "ParallelFor.h"
#include "tofsim/ir/RsmTexels.h"

namespace tofsim::cpu {

namespace {

// The VPL of texel (x, y) of a view (row 0 at the bottom, as GL stores it), or
// nothing when the texel sees no lit surface: a ray where the GL rasterises.
std::optional<ir::Vpl> texelVpl(const rays::RayScene& scene, const capture::Light& light,
                                const ir::RsmView& v, int resolution, int x, int y, double eta,
                                bool gltf, const std::optional<scene::Bounds>& lit) {
  const glm::vec3 direction = ir::rsmTexelDirection(v, resolution, x, y);
  // A Lambertian light's side views look half behind it: no ray there.
  if (light.type == capture::Light::Type::Lambertian && light.angularProfile(direction) <= 0.0f) {
    return std::nullopt;
  }
  if (lit && !rayMeetsBox(light.position_world, direction, *lit)) return std::nullopt;
  const auto hit = scene.intersect(light.position_world, direction);
  if (!hit) return std::nullopt;
  return ir::rsmTexelVpl(
      light, v, resolution, x, y,
      {hit->position_world, hit->normal_world, hit->albedo, hit->metallic, hit->roughness}, eta,
      gltf);
}

}  // namespace

std::vector<ir::Vpl> traceRsmVpls(const rays::RayScene& scene, const capture::Light& light,
                                  int resolution, double indexOfRefraction, bool gltf, int threads,
                                  const std::optional<scene::Bounds>& lit) {
  std::vector<ir::Vpl> vpls;
  for (const ir::RsmView& view : ir::rsmViews(light)) {
    // Rows in parallel, then appended in texel order.
    std::vector<std::vector<ir::Vpl>> rows(static_cast<std::size_t>(resolution));
    parallelFor(rows.size(), threads, [&](std::size_t row) {
      for (int x = 0; x < resolution; ++x) {
        const auto vpl = texelVpl(scene, light, view, resolution, x, static_cast<int>(row),
                                  indexOfRefraction, gltf, lit);
        if (vpl) rows[row].push_back(*vpl);
      }
    });
    for (const auto& row : rows) vpls.insert(vpls.end(), row.begin(), row.end());
  }
  return vpls;
}

}  // namespace tofsim::cpu
