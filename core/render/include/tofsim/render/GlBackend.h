#pragma once
// ir::IrBackend on OpenGL 4.5: the camera's G-buffer by rasterization (or,
// for an imager a rasterizer cannot draw, the driver's traced samples loaded
// into it: setSurfaces), the light's shadow map by rasterization, VPLs from a reflective shadow
// map, imperfect shadow maps (or BVH shadow rays) for their visibility, and compute-shader gathers
// with one thread per pixel, over each pixel's N x N sub-pixel samples (or,
// with render.adaptive_pixel_samples, its one centre sample where the
// driver's mask says so). The driver (ir::IrRenderer) plans and loops; this
// class only runs the passes.

#include <memory>
#include <vector>

#include "tofsim/ir/IrBackend.h"

namespace tofsim::gl {
class Context;
}
namespace tofsim::physics {
struct ResponseKernel;
}

namespace tofsim::render {

class GlBackend : public ir::IrBackend {
 public:
  /// Renders on `context`, which must outlive the backend.
  explicit GlBackend(gl::Context& context);
  /// Renders on a context of its own.
  explicit GlBackend(std::unique_ptr<gl::Context> context);
  ~GlBackend() override;

  std::string description() const override;
  ir::DeviceLimits limits() const override;
  void setScene(const scene::Scene& scene, const rays::RayScene* rays) override;
  /// Keeps the driver's traced samples for the next prepareSurfaces, which
  /// loads them into the G-buffer instead of rasterizing it.
  void setSurfaces(std::unique_ptr<ir::SurfaceImage> samples,
                   std::unique_ptr<ir::SurfaceImage> centres) override;
  ir::CentreSurfaces prepareSurfaces(const capture::RenderJob& job) override;
  void setSampledPixels(const std::vector<uint8_t>& sampled) override;
  std::vector<ir::Vpl> generateVpls(const capture::RenderJob& job) override;
  void setVpls(const std::vector<ir::Vpl>& vpls) override;
  std::size_t fixedBytes() const override;
  std::size_t visibilityBytesPerVpl() const override;
  void allocate(std::size_t pixelsPerSegment, std::size_t vplsPerBatch) override;
  void buildVisibility(std::size_t firstVpl, std::size_t count) override;
  void beginSegment(std::size_t firstPixel, std::size_t count) override;
  void gatherDirect() override;
  void gatherIndirect(std::size_t firstVpl, std::size_t count) override;
  void takeIndirect(float* indirect) override;
  void readSegment(float* direct, float* indirect, AxisLoss& offAxis) override;

  /// The response classes (core/physics/temporal_response.md), taken at the
  /// next allocate; the default table keeps only the instant class.
  void setResponseClasses(const physics::ResponseClassTable& classes) override;

 private:
  struct SceneObjects;  // the scene's GL objects, kept across renders (GlBackend.cpp)
  struct Passes;        // one render's GL objects (GlBackend.cpp)
  Passes& passes() const;
  /// prepareSurfaces' G-buffer of a pinhole: rasterized.
  ir::CentreSurfaces rasterizeSurfaces(Passes& p) const;
  /// prepareSurfaces' G-buffer of another imager: setSurfaces' samples.
  ir::CentreSurfaces loadGivenSurfaces(Passes& p);

  std::unique_ptr<gl::Context> ownedContext_;
  gl::Context& context_;
  // Declared before passes_: a render's objects go first.
  std::unique_ptr<SceneObjects> sceneObjects_;
  std::unique_ptr<Passes> passes_;
  std::unique_ptr<ir::SurfaceImage> givenSamples_, givenCentres_;  ///< setSurfaces', until used
  physics::ResponseClassTable responseClasses_;  ///< setResponseClasses'
};

}  // namespace tofsim::render
