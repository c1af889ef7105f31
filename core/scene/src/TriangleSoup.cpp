#include "tofsim/scene/TriangleSoup.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <numeric>

namespace tofsim::scene {

namespace {

struct Box {
  glm::vec3 lo{std::numeric_limits<float>::max()};
  glm::vec3 hi{std::numeric_limits<float>::lowest()};
  void grow(const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void grow(const Box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  float area() const {
    const glm::vec3 d = glm::max(hi - lo, glm::vec3(0.0f));
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
};

struct Triangle {
  std::array<glm::vec3, 3> p;
  Box box;
  glm::vec3 centroid;
};

float bitsAsFloat(uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

constexpr int kBins = 12;
constexpr std::size_t kLeafSize = 4;

class BvhBuilder {
 public:
  explicit BvhBuilder(std::vector<Triangle>& tris) : tris_(tris) {}
  std::vector<BvhNode> build() {
    if (!tris_.empty()) buildNode(0, tris_.size(), 1);
    return std::move(nodes_);
  }
  int depth() const { return depth_; }

 private:
  // Builds the subtree over tris_[begin, end) and returns its node index.
  std::size_t buildNode(std::size_t begin, std::size_t end, int depth) {
    depth_ = std::max(depth_, depth);
    Box bounds, centroids;
    for (std::size_t i = begin; i < end; ++i) {
      bounds.grow(tris_[i].box);
      centroids.grow(tris_[i].centroid);
    }
    const std::size_t index = nodes_.size();
    nodes_.push_back({glm::vec4(bounds.lo, 0.0f), glm::vec4(bounds.hi, 0.0f)});
    const std::size_t mid = split(begin, end, centroids);
    if (mid == begin || mid == end) {
      nodes_[index].min.w = bitsAsFloat(static_cast<uint32_t>(begin));
      nodes_[index].max.w = bitsAsFloat(static_cast<uint32_t>(end - begin));
      return index;
    }
    buildNode(begin, mid, depth + 1);
    const std::size_t right = buildNode(mid, end, depth + 1);
    nodes_[index].min.w = bitsAsFloat(static_cast<uint32_t>(right));
    nodes_[index].max.w = bitsAsFloat(0u);
    return index;
  }

  // Binned SAH split along the widest centroid axis; returns begin when a
  // leaf is cheaper.
  std::size_t split(std::size_t begin, std::size_t end, const Box& centroids) {
    const std::size_t n = end - begin;
    if (n <= kLeafSize) return begin;
    const glm::vec3 extent = centroids.hi - centroids.lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    if (extent[axis] <= 0.0f) return begin;
    const auto binOf = [&](const Triangle& t) {
      const int b =
          static_cast<int>(kBins * (t.centroid[axis] - centroids.lo[axis]) / extent[axis]);
      return std::clamp(b, 0, kBins - 1);
    };
    std::array<Box, kBins> boxes;
    std::array<std::size_t, kBins> counts{};
    for (std::size_t i = begin; i < end; ++i) {
      const int b = binOf(tris_[i]);
      boxes[b].grow(tris_[i].box);
      ++counts[b];
    }
    float bestCost = std::numeric_limits<float>::max();
    int bestSplit = -1;
    for (int s = 1; s < kBins; ++s) {
      Box left, right;
      std::size_t nl = 0, nr = 0;
      for (int b = 0; b < s; ++b) {
        if (counts[b]) left.grow(boxes[b]);
        nl += counts[b];
      }
      for (int b = s; b < kBins; ++b) {
        if (counts[b]) right.grow(boxes[b]);
        nr += counts[b];
      }
      if (nl == 0 || nr == 0) continue;
      const float cost = left.area() * nl + right.area() * nr;
      if (cost < bestCost) {
        bestCost = cost;
        bestSplit = s;
      }
    }
    if (bestSplit < 0) return begin;
    const auto mid = std::stable_partition(tris_.begin() + static_cast<long>(begin),
                                           tris_.begin() + static_cast<long>(end),
                                           [&](const Triangle& t) { return binOf(t) < bestSplit; });
    return static_cast<std::size_t>(mid - tris_.begin());
  }

  std::vector<Triangle>& tris_;
  std::vector<BvhNode> nodes_;
  int depth_ = 0;
};

}  // namespace

TriangleSoup buildTriangleSoup(const Scene& scene) {
  std::vector<Triangle> tris;
  for (const Mesh& mesh : scene.meshes) {
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      Triangle t;
      for (int k = 0; k < 3; ++k) {
        t.p[k] = mesh.positions_world[mesh.indices[i + k]];
        t.box.grow(t.p[k]);
      }
      t.centroid = (t.p[0] + t.p[1] + t.p[2]) / 3.0f;
      tris.push_back(t);
    }
  }
  TriangleSoup soup;
  BvhBuilder builder(tris);
  soup.bvh = builder.build();
  soup.bvhDepth = builder.depth();
  std::vector<double> areas;
  for (const Triangle& t : tris) {
    for (const glm::vec3& p : t.p) soup.corners.emplace_back(p, 1.0f);
    areas.push_back(
        0.5 * glm::length(glm::cross(glm::dvec3(t.p[1] - t.p[0]), glm::dvec3(t.p[2] - t.p[0]))));
  }
  soup.totalArea_m2 = std::accumulate(areas.begin(), areas.end(), 0.0);
  double running = 0.0;
  for (double a : areas) {
    running += a;
    soup.areaCdf.push_back(static_cast<float>(running / soup.totalArea_m2));
  }
  if (!soup.areaCdf.empty()) soup.areaCdf.back() = 1.0f;
  return soup;
}

}  // namespace tofsim::scene
