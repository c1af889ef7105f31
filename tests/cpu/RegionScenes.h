#pragma once
// What the per-region media tests share (issue 42's `media:`;
// MediumRegionsTest.cpp, ScatteringRegionsTest.cpp): a box mesh to take out
// of the surfaces as a region, the reference's render of a job, a volume's
// energy.

#include <array>
#include <string>

#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/reference/ReferenceRenderer.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::test {

/// A box mesh named `name` with 8 shared corners, wound outwards (or inwards).
inline void addBox(scene::Scene& scene, const std::string& name, glm::vec3 lo, glm::vec3 hi,
                   bool inwards = false) {
  scene::Mesh m;
  m.name = name;
  for (int i = 0; i < 8; ++i) {
    m.positions_world.emplace_back(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    m.normals_world.emplace_back(0.0f, 0.0f, 1.0f);
  }
  const glm::vec3 centre = 0.5f * (lo + hi);
  // Each face's 4 corners in order around it.
  const int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    for (const auto& t : {std::array<int, 3>{f[0], f[1], f[2]}, std::array<int, 3>{f[0], f[2], f[3]}}) {
      const glm::vec3 a = m.positions_world[t[0]], b = m.positions_world[t[1]],
                      c = m.positions_world[t[2]];
      const bool out = glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0f - centre) > 0.0f;
      const bool flip = out == inwards;
      m.indices.insert(m.indices.end(), {static_cast<uint32_t>(t[0]),
                                         static_cast<uint32_t>(flip ? t[2] : t[1]),
                                         static_cast<uint32_t>(flip ? t[1] : t[2])});
    }
  }
  scene.meshes.push_back(std::move(m));
}

/// The reference's render of `job` (point pixels, 2 threads).
inline capture::VolumeCollector renderReference(const capture::RenderJob& job, int32_t bounces,
                                                int32_t samples) {
  reference::ReferenceSettings s;
  s.pixel_filter = reference::PixelFilter::Point;
  s.bounces = bounces;
  s.samples_per_pixel = samples;
  s.threads = 2;
  capture::VolumeCollector out(job.camera().width, job.camera().height, job.settings.time, 3);
  reference::ReferenceRenderer(s).render(job, out);
  return out;
}

/// The sum of every value of a volume.
inline double energy(const TransientVolume& v) {
  double sum = 0.0;
  for (const float x : v.values()) sum += x;
  return sum;
}

}  // namespace tofsim::test
