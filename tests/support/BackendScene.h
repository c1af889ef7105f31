#pragma once
// A backend driven by hand (without ir::IrRenderer) gets its scene set as the
// driver sets it: one RayScene of the scene, held as long as the backend
// renders it.

#include "tofsim/ir/IrBackend.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/scene/Scene.h"

namespace tofsim::test {

class BackendScene {
 public:
  BackendScene(ir::IrBackend& backend, const scene::Scene& scene) : rays_(scene, 0) {
    backend.setScene(scene, &rays_);
  }

 private:
  rays::RayScene rays_;
};

}  // namespace tofsim::test
