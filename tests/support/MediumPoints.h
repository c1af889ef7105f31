#pragma once
// Points below, beside and above a point light, seen from `origin`, as given
// samples (IrBackend::setSurfaces) of a point-set imager; a quad far below
// stands for the scene (nothing between the light and a point). Medium
// points (physics::VERTEX_MEDIUM) receive albedo / (4 pi) * I / r^2 from
// every side, in the bin of |l - x| + |x - origin|.

#include <vector>

#include "support/AnalyticScenes.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/capture/RenderJob.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::test {

// Given samples (IrBackend::setSurfaces), one per point of an N x 1 image:
// point p's vertex of models[p] with `albedo`, shading normal n and
// triangle normal `geometric` (0 and anything for a medium point).
inline ir::SurfaceImage givenSamples(const std::vector<glm::vec3>& points,
                                     const std::vector<int>& models, const glm::vec3& albedo,
                                     const glm::vec3& n, const glm::vec3& geometric) {
  ir::SurfaceImage s;
  s.width = static_cast<int32_t>(points.size());
  s.height = 1;
  for (std::size_t p = 0; p <= points.size(); ++p) s.firstSample.push_back(p);
  s.side.assign(points.size(), 1);
  for (std::size_t p = 0; p < points.size(); ++p) {
    s.position.emplace_back(points[p], 1.0f);
    s.normal.emplace_back(n, 0.0f);
    s.vertex.push_back(physics::scatterVertex(models[p], albedo, 0.0f, 1.0f));
    s.geometric.push_back(geometric);
  }
  return s;
}

struct MediumPoints {
  scene::Scene scene;
  capture::RenderJob job;
  glm::vec3 albedo{0.6f, 0.5f, 0.4f};
  glm::vec3 origin{0.0f, -2.0f, 0.0f};
  std::vector<glm::vec3> points{{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 2.5f}};

  MediumPoints() {
    addQuad(scene, glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0, 0, 1), 1.0f, glm::vec3(0.5f));
    job.scene = &scene;
    capture::PointSetImager imager;
    imager.width = static_cast<int32_t>(points.size());
    imager.points_world = points;
    imager.origin_world = origin;
    job.imager = imager;
    job.light.position_world = {0.0f, 0.0f, 1.0f};
    job.light.intensity_W_per_sr = glm::vec3(2.0f, 1.0f, 0.5f);
    job.settings.indirect.enabled = false;
    job.settings.pixel_footprint = false;
    job.settings.time = TimeAxis{0.0, 0.005 / kSpeedOfLight_m_per_s, 2000};
  }

  // One sample per point: vertices of models[p] (all of `model` if empty),
  // normal n (0 for a medium).
  ir::SurfaceImage samples(int model, const glm::vec3& n, std::vector<int> models = {}) const {
    if (models.empty()) models.assign(points.size(), model);
    return givenSamples(points, models, albedo, n, n);
  }
};

}  // namespace tofsim::test
