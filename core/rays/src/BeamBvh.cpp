#include "BeamBvh.h"

#include <emmintrin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

namespace tofsim::rays::detail {

BundleIsa bundleIsaFor(const char* embreeIsa) {
  const bool avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
                      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw") &&
                      __builtin_cpu_supports("avx512vl");
  const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
                    __builtin_cpu_supports("bmi2");
  const char* isa = embreeIsa == nullptr ? "" : embreeIsa;
  if (std::strcmp(isa, "") == 0)
    return avx512 ? BundleIsa::Avx512 : avx2 ? BundleIsa::Avx2 : BundleIsa::None;
  if (std::strcmp(isa, "avx512") == 0 && avx512) return BundleIsa::Avx512;
  if (std::strcmp(isa, "avx2") == 0 && avx2) return BundleIsa::Avx2;
  return BundleIsa::None;  // an older instruction set: Embree traces
}

namespace {

struct V3 {
  float x, y, z;
};
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator*(float s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
float dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
V3 normalize(V3 a) { return (1.0f / std::sqrt(dot(a, a))) * a; }
V3 absv(V3 a) { return {std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}; }
float sum(V3 a) { return a.x + a.y + a.z; }

V3 vertex(const float* p) { return {p[0], p[1], p[2]}; }

// The four planes through the origin that bound a bundle's rays (inward
// normals, one per lane), with a margin far above float rounding: a point
// counts as outside a plane only when it is outside by more than 1e-5 of
// its distance (and a box by 1e-5 of its distance and size).
struct Pyramid {
  V3 origin;
  __m128 nx, ny, nz;                        // the planes' normals
  __m128 ax, ay, az;                        // their absolute values
  bool outside(V3 centre, V3 half) const {  // a box: centre and half extents
    const V3 c = centre - origin;
    const float margin = 1e-5f * (sum(absv(c)) + sum(half));
    const __m128 s = _mm_add_ps(
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, _mm_set1_ps(c.x)), _mm_mul_ps(ny, _mm_set1_ps(c.y))),
                   _mm_mul_ps(nz, _mm_set1_ps(c.z))),
        _mm_add_ps(
            _mm_add_ps(_mm_mul_ps(ax, _mm_set1_ps(half.x)), _mm_mul_ps(ay, _mm_set1_ps(half.y))),
            _mm_mul_ps(az, _mm_set1_ps(half.z))));
    return _mm_movemask_ps(_mm_cmplt_ps(s, _mm_set1_ps(-margin))) != 0;
  }
  // All three vertices outside one plane.
  bool outside(const BundleTriangle& t) const {
    __m128 all = _mm_castsi128_ps(_mm_set1_epi32(-1));
    for (const float* v : {t.v0, t.v1, t.v2}) {
      const V3 q = vertex(v) - origin;
      const __m128 s =
          _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, _mm_set1_ps(q.x)), _mm_mul_ps(ny, _mm_set1_ps(q.y))),
                     _mm_mul_ps(nz, _mm_set1_ps(q.z)));
      all = _mm_and_ps(all, _mm_cmplt_ps(s, _mm_set1_ps(-1e-5f * sum(absv(q)))));
    }
    return _mm_movemask_ps(all) != 0;
  }
};

}  // namespace

struct BeamBvh::Item {
  V3 lo, hi, centre;
  int32_t index;
};

BeamBvh::BeamBvh(std::vector<BundleTriangle> triangles, BundleIsa isa) {
  if (isa == BundleIsa::Avx512) {
    intersect_ = intersectAvx512;
    finish_ = finishAvx512;
  } else if (isa == BundleIsa::Avx2) {
    intersect_ = intersectAvx2;
    finish_ = finishAvx2;
  }
  std::vector<Item> items(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const V3 a = vertex(triangles[i].v0), b = vertex(triangles[i].v1), c = vertex(triangles[i].v2);
    Item& it = items[i];
    it.lo = {std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::min({a.z, b.z, c.z})};
    it.hi = {std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}), std::max({a.z, b.z, c.z})};
    it.centre = 0.5f * (it.lo + it.hi);
    it.index = static_cast<int32_t>(i);
  }
  nodes_.reserve(2 * triangles.size() + 1);
  nodes_.push_back({});
  if (!items.empty()) build(items, 0, 0, static_cast<int32_t>(items.size()), 0);
  order_.resize(items.size());
  triangles_.resize(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    order_[i] = items[i].index;
    triangles_[i] = triangles[items[i].index];
  }
  refitBoxes();
}

// Binned SAH over the triangles' box centres; leaves of kLeafTriangles at
// most (a median split where the bins cannot separate them, and below
// depth kSahDepth: the traversal's stack holds the tree's depth).
void BeamBvh::build(std::vector<Item>& items, int32_t node, int32_t begin, int32_t end, int depth) {
  constexpr int kSahDepth = 48;
  const int32_t count = end - begin;
  if (count <= kLeafTriangles) {
    nodes_[node].first = begin;
    nodes_[node].count = count;
    return;
  }
  V3 clo = items[begin].centre, chi = clo;
  for (int32_t i = begin; i < end; ++i) {
    const V3 c = items[i].centre;
    clo = {std::min(clo.x, c.x), std::min(clo.y, c.y), std::min(clo.z, c.z)};
    chi = {std::max(chi.x, c.x), std::max(chi.y, c.y), std::max(chi.z, c.z)};
  }
  const V3 extent = chi - clo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const auto along = [axis](V3 v) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; };
  const float lo = along(clo), width = along(extent);
  int32_t mid = begin + count / 2;
  if (width > 0.0f && depth < kSahDepth) {
    constexpr int kBins = 16;
    struct Bin {
      V3 lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
            std::numeric_limits<float>::max()};
      V3 hi{-std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
            -std::numeric_limits<float>::max()};
      int32_t count = 0;
    };
    std::array<Bin, kBins> bins;
    const auto binOf = [&](const Item& it) {
      return std::min(kBins - 1, static_cast<int>((along(it.centre) - lo) / width * kBins));
    };
    const auto grow = [](Bin& b, V3 l, V3 h) {
      b.lo = {std::min(b.lo.x, l.x), std::min(b.lo.y, l.y), std::min(b.lo.z, l.z)};
      b.hi = {std::max(b.hi.x, h.x), std::max(b.hi.y, h.y), std::max(b.hi.z, h.z)};
    };
    for (int32_t i = begin; i < end; ++i) {
      Bin& b = bins[binOf(items[i])];
      grow(b, items[i].lo, items[i].hi);
      ++b.count;
    }
    const auto area = [](const Bin& b) {
      if (b.count == 0) return 0.0f;
      const V3 e = b.hi - b.lo;
      return e.x * e.y + e.y * e.z + e.z * e.x;
    };
    std::array<float, kBins> leftCost{};
    Bin acc;
    for (int k = 0; k < kBins - 1; ++k) {
      if (bins[k].count > 0) grow(acc, bins[k].lo, bins[k].hi);
      acc.count += bins[k].count;
      leftCost[k] = area(acc) * acc.count;
    }
    acc = Bin{};
    float bestCost = std::numeric_limits<float>::max();
    int bestSplit = -1;
    for (int k = kBins - 1; k > 0; --k) {
      if (bins[k].count > 0) grow(acc, bins[k].lo, bins[k].hi);
      acc.count += bins[k].count;
      const float cost = leftCost[k - 1] + area(acc) * acc.count;
      if (acc.count < count && acc.count > 0 && cost < bestCost) {
        bestCost = cost;
        bestSplit = k;
      }
    }
    if (bestSplit > 0) {
      mid = static_cast<int32_t>(
          std::partition(items.begin() + begin, items.begin() + end,
                         [&](const Item& it) { return binOf(it) < bestSplit; }) -
          items.begin());
    }
  }
  if (mid <= begin || mid >= end) {
    mid = begin + count / 2;
    std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                     [&](const Item& a, const Item& b) {
                       return along(a.centre) < along(b.centre) ||
                              (along(a.centre) == along(b.centre) && a.index < b.index);
                     });
  }
  const auto left = static_cast<int32_t>(nodes_.size());
  nodes_.push_back({});
  nodes_.push_back({});
  nodes_[node].first = left;
  nodes_[node].count = 0;
  build(items, left, begin, mid, depth + 1);
  build(items, left + 1, mid, end, depth + 1);
}

void BeamBvh::refit(const std::vector<BundleTriangle>& triangles) {
  for (std::size_t i = 0; i < triangles_.size(); ++i) triangles_[i] = triangles[order_[i]];
  refitBoxes();
}

void BeamBvh::refitBoxes() {
  constexpr float kMax = std::numeric_limits<float>::max();
  std::vector<std::array<V3, 2>> boxes(nodes_.size());                   // lo, hi
  for (auto n = static_cast<int64_t>(nodes_.size()) - 1; n >= 0; --n) {  // children first
    Node& node = nodes_[n];
    V3 lo{kMax, kMax, kMax}, hi{-kMax, -kMax, -kMax};
    const auto grow = [&](V3 l, V3 h) {
      lo = {std::min(lo.x, l.x), std::min(lo.y, l.y), std::min(lo.z, l.z)};
      hi = {std::max(hi.x, h.x), std::max(hi.y, h.y), std::max(hi.z, h.z)};
    };
    if (node.count > 0) {
      for (int32_t i = node.first; i < node.first + node.count; ++i) {
        const BundleTriangle& t = triangles_[i];
        for (const float* p : {t.v0, t.v1, t.v2}) grow(vertex(p), vertex(p));
      }
    } else if (node.first > 0) {
      for (int32_t c : {node.first, node.first + 1}) grow(boxes[c][0], boxes[c][1]);
    }
    boxes[n] = {lo, hi};
    // Rounded outward: the box holds its triangles whatever the rounding.
    const V3 centre = 0.5f * (lo + hi), half = 0.5f * (hi - lo);
    const float pad = 1e-6f * (sum(absv(centre)) + sum(half));
    node.centre = {centre.x, centre.y, centre.z};
    node.half = {half.x + pad, half.y + pad, half.z + pad};
  }
}

bool BeamBvh::trace(BundleRays& rays) const {
  if (intersect_ == nullptr) return false;
  // The bundle's mean direction and the pyramid about it that holds every
  // ray: tangent tau of the widest ray off the axis along u or v, widened.
  V3 mean{0.0f, 0.0f, 0.0f};
  for (int i = 0; i < kBundleLanes; ++i) {
    if (rays.active[i] != 0) mean = mean + V3{rays.dx[i], rays.dy[i], rays.dz[i]};
  }
  if (!(dot(mean, mean) > 0.0f)) return false;
  const V3 axis = normalize(mean);
  const V3 u = normalize(cross(axis, std::fabs(axis.x) < 0.9f ? V3{1, 0, 0} : V3{0, 1, 0}));
  const V3 v = cross(axis, u);
  float tau = 0.0f;
  for (int i = 0; i < kBundleLanes; ++i) {
    if (rays.active[i] == 0) continue;
    const V3 d{rays.dx[i], rays.dy[i], rays.dz[i]};
    const float a = dot(axis, d);
    if (!(a > 0.7f)) return false;
    tau = std::max(tau, std::max(std::fabs(dot(u, d)), std::fabs(dot(v, d))) / a);
  }
  tau = tau * 1.001f + 1e-6f;
  Pyramid pyramid;
  pyramid.origin = {rays.ox, rays.oy, rays.oz};
  const V3 n[4] = {tau * axis - u, tau * axis + u, tau * axis - v, tau * axis + v};
  pyramid.nx = _mm_setr_ps(n[0].x, n[1].x, n[2].x, n[3].x);
  pyramid.ny = _mm_setr_ps(n[0].y, n[1].y, n[2].y, n[3].y);
  pyramid.nz = _mm_setr_ps(n[0].z, n[1].z, n[2].z, n[3].z);
  const __m128 sign = _mm_set1_ps(-0.0f);
  pyramid.ax = _mm_andnot_ps(sign, pyramid.nx);
  pyramid.ay = _mm_andnot_ps(sign, pyramid.ny);
  pyramid.az = _mm_andnot_ps(sign, pyramid.nz);

  constexpr float kInf = std::numeric_limits<float>::infinity();
  for (int i = 0; i < kBundleLanes; ++i) {
    rays.t[i] = kInf;
    rays.hit[i] = -1;
    rays.tie[i] = 0;
    rays.edgeT[i] = kInf;
  }
  // Nothing beyond the farthest ray's hit so far can matter (t is the
  // distance along a unit direction: at least the box's distance).
  float reach2 = kInf;
  const auto distance2 = [&](const Node& n) {
    const V3 c = absv(V3{n.centre.x, n.centre.y, n.centre.z} - pyramid.origin);
    const float dx = std::max(c.x - n.half.x, 0.0f), dy = std::max(c.y - n.half.y, 0.0f),
                dz = std::max(c.z - n.half.z, 0.0f);
    return dx * dx + dy * dy + dz * dz;
  };
  const auto touches = [&](const Node& n, float& d2) {
    d2 = distance2(n);
    return d2 <= reach2 && !pyramid.outside(V3{n.centre.x, n.centre.y, n.centre.z},
                                            V3{n.half.x, n.half.y, n.half.z});
  };
  std::array<int32_t, 128> stack;
  int top = 0;
  float rootD2 = 0.0f;
  if (!nodes_.empty() && !triangles_.empty() && touches(nodes_[0], rootD2)) stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (node.count == 0) {
      float d2[2];
      const bool in[2] = {touches(nodes_[node.first], d2[0]),
                          touches(nodes_[node.first + 1], d2[1])};
      const int nearer = d2[1] < d2[0] ? 1 : 0;
      if (in[1 - nearer]) stack[top++] = node.first + 1 - nearer;  // the farther, later
      if (in[nearer]) stack[top++] = node.first + nearer;
      continue;
    }
    if (distance2(node) > reach2) continue;  // a hit found since it was pushed
    int32_t candidates[kLeafTriangles];
    int n = 0;
    for (int32_t i = node.first; i < node.first + node.count; ++i) {
      if (!pyramid.outside(triangles_[i])) candidates[n++] = i;
    }
    if (n == 0) continue;
    intersect_(rays, triangles_.data(), candidates, n);
    float farthest = 0.0f;
    for (int i = 0; i < kBundleLanes; ++i) {
      if (rays.active[i] != 0) farthest = std::max(farthest, rays.t[i]);
    }
    const float reach = farthest * 1.0001f;
    reach2 = reach * reach;
  }
  finish_(rays);
  return true;
}

}  // namespace tofsim::rays::detail
