#pragma once
// A scene ready for core/lidar's tracing in a test: the scene, its Embree
// rays on one thread and the WaveformScene that points at them, Lambertian
// vertices (the lidar tests' one setup, written once).

#include <utility>

#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/lidar/DirectWaveforms.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::test {

struct TracedScene {
  explicit TracedScene(scene::Scene s) : scene(std::move(s)), rays(scene, 1) {
    traced.rays = &rays;
    traced.materials = ir::materialVertices(scene, physics::VERTEX_LAMBERTIAN);
  }
  scene::Scene scene;
  rays::RayScene rays;
  lidar::WaveformScene traced;
};

}  // namespace tofsim::test
