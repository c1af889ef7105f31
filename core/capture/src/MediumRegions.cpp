#include "tofsim/capture/MediumRegions.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tofsim/scene/RegionMeshes.h"
#include "tofsim/util/Error.h"

namespace tofsim::capture {

namespace {

// A crossing of a line with a region's surface: at t, entering or leaving.
struct Crossing {
  double t;
  bool entering;
};

// Moeller-Trumbore on the whole line (any t), in double.
bool lineHits(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3* tri, Crossing& out) {
  const glm::dvec3 e1 = tri[1] - tri[0];
  const glm::dvec3 e2 = tri[2] - tri[0];
  const glm::dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (det == 0.0) return false;  // parallel: the line grazes, no crossing
  const double inv = 1.0 / det;
  const glm::dvec3 s = o - tri[0];
  const double u = glm::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return false;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  out.t = glm::dot(e2, q) * inv;
  out.entering = glm::dot(d, glm::cross(e1, e2)) < 0.0;  // against the outward normal
  return true;
}

// Whether the line misses the box (slabs, any t).
bool lineMissesBox(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& lo,
                   const glm::dvec3& hi) {
  double t0 = -std::numeric_limits<double>::infinity();
  double t1 = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (o[a] < lo[a] || o[a] > hi[a]) return true;
      continue;
    }
    double ta = (lo[a] - o[a]) / d[a];
    double tb = (hi[a] - o[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 > t1;
}

}  // namespace

MediumRegions::MediumRegions(const std::vector<RegionMedium>& media, const scene::Scene& scene,
                             double axisIndex) {
  for (const RegionMedium& m : media) {
    const auto mesh = std::find_if(scene.regions.begin(), scene.regions.end(),
                                   [&](const scene::RegionMesh& r) { return r.name == m.region; });
    TOFSIM_CHECK(mesh != scene.regions.end());  // configureScene resolved every region
    Region r;
    r.params = m;
    r.delayPerMetre = m.index_of_refraction / axisIndex - 1.0;
    for (const glm::vec3& p : mesh->triangles_world) r.triangles.emplace_back(p);
    const scene::Bounds b = scene::regionBounds(*mesh);
    r.lo = glm::dvec3(b.min);
    r.hi = glm::dvec3(b.max);
    regions_.push_back(std::move(r));
  }
}

bool MediumRegions::scatters() const {
  return std::any_of(regions_.begin(), regions_.end(),
                     [](const Region& r) { return r.params.medium.scatters(); });
}

void MediumRegions::lineSpans(const Region& r, int32_t index, const glm::dvec3& origin,
                              const glm::dvec3& dir, std::vector<RegionSpan>& out) const {
  if (lineMissesBox(origin, dir, r.lo, r.hi)) return;
  // Scratch kept per thread: a leg's passage allocates nothing (the CPU
  // gather asks once per pixel and VPL).
  thread_local std::vector<Crossing> crossings;
  crossings.clear();
  for (std::size_t i = 0; i + 2 < r.triangles.size(); i += 3) {
    Crossing c{};
    if (lineHits(origin, dir, &r.triangles[i], c)) crossings.push_back(c);
  }
  std::sort(crossings.begin(), crossings.end(),
            [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
  // A line through an edge or a vertex crosses several triangles at one t:
  // one crossing of each kind there.
  const double eps = 1e-9 * (1.0 + glm::length(r.hi - r.lo));
  int depth = 0;
  double start = 0.0;
  for (std::size_t i = 0; i < crossings.size(); ++i) {
    const Crossing& c = crossings[i];
    bool repeat = false;
    for (std::size_t j = i; j-- > 0 && c.t - crossings[j].t <= eps;) {
      repeat = repeat || crossings[j].entering == c.entering;
    }
    if (repeat) continue;
    if (c.entering) {
      if (depth++ == 0) start = c.t;
    } else if (depth > 0 && --depth == 0) {
      out.push_back({start, c.t, index});
    }
  }
}

void MediumRegions::spans(const glm::dvec3& origin, const glm::dvec3& dir, double length_m,
                          std::vector<RegionSpan>& out) const {
  out.clear();
  thread_local std::vector<RegionSpan> line;
  line.clear();
  for (std::size_t r = 0; r < regions_.size(); ++r) {
    lineSpans(regions_[r], static_cast<int32_t>(r), origin, dir, line);
  }
  for (const RegionSpan& s : line) {
    const double t0 = std::max(s.t0_m, 0.0);
    const double t1 = std::min(s.t1_m, length_m);
    if (t1 > t0) out.push_back({t0, t1, s.region});
  }
  std::sort(out.begin(), out.end(),
            [](const RegionSpan& a, const RegionSpan& b) { return a.t0_m < b.t0_m; });
}

RegionPassage MediumRegions::passage(const glm::dvec3& a, const glm::dvec3& b) const {
  RegionPassage p;
  const double length = glm::length(b - a);
  if (regions_.empty() || !(length > 0.0)) return p;
  thread_local std::vector<RegionSpan> inside;
  spans(a, (b - a) / length, length, inside);
  for (const RegionSpan& s : inside) {
    const Region& r = regions_[static_cast<std::size_t>(s.region)];
    const double l = s.t1_m - s.t0_m;
    p.opticalDepth += glm::dvec3(r.params.medium.sigmaT()) * l;
    p.extraPath_m += r.delayPerMetre * l;
  }
  return p;
}

}  // namespace tofsim::capture
