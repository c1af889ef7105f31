#include "tofsim/scene/RegionMeshes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>
#include <utility>

namespace tofsim::scene {

namespace {

using Key = std::tuple<float, float, float>;
Key keyOf(const glm::vec3& p) { return {p.x, p.y, p.z}; }

std::string pointText(const glm::vec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", static_cast<double>(p.x),
                static_cast<double>(p.y), static_cast<double>(p.z));
  return text;
}

// Six times the signed volume the triangles enclose (positive: wound out).
double signedVolume6(const std::vector<glm::vec3>& t) {
  double v = 0.0;
  for (std::size_t i = 0; i + 2 < t.size(); i += 3) {
    v += glm::dot(glm::dvec3(t[i]), glm::cross(glm::dvec3(t[i + 1]), glm::dvec3(t[i + 2])));
  }
  return v;
}

}  // namespace

std::optional<RegionMesh> takeRegionMesh(Scene& scene, const std::string& name) {
  RegionMesh region{name, {}};
  bool found = false;
  auto named = [&](const Mesh& m) { return m.name == name || m.node == name; };
  for (const Mesh& m : scene.meshes) {
    if (!named(m)) continue;
    found = true;
    for (uint32_t i : m.indices) region.triangles_world.push_back(m.positions_world[i]);
  }
  if (!found) return std::nullopt;
  scene.meshes.erase(std::remove_if(scene.meshes.begin(), scene.meshes.end(), named),
                     scene.meshes.end());
  if (signedVolume6(region.triangles_world) < 0.0) {
    for (std::size_t i = 0; i + 2 < region.triangles_world.size(); i += 3) {
      std::swap(region.triangles_world[i + 1], region.triangles_world[i + 2]);
    }
  }
  return region;
}

std::string regionMeshProblem(const RegionMesh& region) {
  const std::vector<glm::vec3>& t = region.triangles_world;
  if (t.empty()) return "has no triangles";
  // Each directed edge, welded by position: how often each way.
  std::map<std::pair<Key, Key>, int> directed;
  for (std::size_t i = 0; i + 2 < t.size(); i += 3) {
    for (int e = 0; e < 3; ++e) {
      const Key a = keyOf(t[i + e]);
      const Key b = keyOf(t[i + (e + 1) % 3]);
      if (a == b) continue;  // a degenerate triangle's collapsed edge
      ++directed[{a, b}];
    }
  }
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    const int back = reverse == directed.end() ? 0 : reverse->second;
    const glm::vec3 a(std::get<0>(edge.first), std::get<1>(edge.first), std::get<2>(edge.first));
    const glm::vec3 b(std::get<0>(edge.second), std::get<1>(edge.second),
                      std::get<2>(edge.second));
    const std::string where = " (the edge " + pointText(a) + " - " + pointText(b) + ")";
    if (count + back == 1) return "is not closed: an edge has one triangle" + where;
    if (count + back > 2) return "is not a closed surface: an edge has more than two triangles" + where;
    if (count != 1) {
      return "is not consistently wound: two triangles cross an edge the same way" + where;
    }
  }
  if (!(std::abs(signedVolume6(t)) > 0.0)) return "encloses no volume";
  return "";
}

Bounds regionBounds(const RegionMesh& region) {
  Bounds b;
  if (region.triangles_world.empty()) return b;
  b.min = b.max = region.triangles_world.front();
  for (const glm::vec3& p : region.triangles_world) {
    b.min = glm::min(b.min, p);
    b.max = glm::max(b.max, p);
  }
  return b;
}

}  // namespace tofsim::scene
