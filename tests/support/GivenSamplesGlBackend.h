#pragma once
// The GL backend given `given` in place of the samples the driver traces
// for a point set (the driver's medium points would come this way), on the
// test program's shared context.

#include <memory>

#include "support/GlTestContext.h"
#include "tofsim/ir/SurfaceImage.h"
#include "tofsim/render/GlBackend.h"

namespace tofsim::test {

class GivenSamplesGlBackend : public render::GlBackend {
 public:
  explicit GivenSamplesGlBackend(ir::SurfaceImage given)
      : GlBackend(glTestContext()), given_(std::move(given)) {}
  void setSurfaces(std::unique_ptr<ir::SurfaceImage> /*traced*/,
                   std::unique_ptr<ir::SurfaceImage> /*centres*/) override {
    GlBackend::setSurfaces(std::make_unique<ir::SurfaceImage>(given_), nullptr);
  }

 private:
  ir::SurfaceImage given_;
};

}  // namespace tofsim::test
