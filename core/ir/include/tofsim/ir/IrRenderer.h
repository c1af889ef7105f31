#pragma once
// Transient instant radiosity (Pan, Arellano, Jarabo 2019), independent of
// the device: validates the job against the backend's limits, plans memory
// (pixel segments, VPL batches), runs the segment x VPL-batch loop on the
// backend and adds the light seen straight by the camera. Every contribution
// lands in the time bin of its full optical path.
//
// The volume is produced in segments sized by the memory budget and the
// device's limits and handed to a SegmentSink as soon as each is done, with
// the components "direct", "indirect" and "bounce1" .. "bounceN"
// (N = render.indirect.bounces; indirect = their float sum in bounce order).

#include <cstddef>
#include <memory>

#include "tofsim/capture/Renderer.h"
#include "tofsim/ir/IrBackend.h"

namespace tofsim::ir {

class IrRenderer : public capture::Renderer {
 public:
  explicit IrRenderer(std::unique_ptr<IrBackend> backend);
  ~IrRenderer() override;

  std::string description() const override;
  /// Not thread-safe: the backend holds one render's state at a time. The
  /// scene is prepared (IrBackend::setScene, one Embree BVH) when job.scene
  /// is not the scene of the last render, so a sequence of captures of one
  /// scene (laser positions of a scan, lights, cameras) prepares it once.
  capture::RenderResult render(const capture::RenderJob& job, capture::SegmentSink& sink,
                               const capture::ProgressCallback& progress = {}) const override;
  /// The held scene was changed in place (an animation's next frame): the
  /// next render prepares it again.
  void sceneChanged() const override;
  /// How many times a scene was prepared (for tests and statistics).
  std::size_t scenePreparations() const { return scenePreparations_; }

 private:
  void prepareScene(const scene::Scene& scene) const;
  /// The held scene's RayScene, built on first use.
  const rays::RayScene& rays() const;

  std::unique_ptr<IrBackend> backend_;
  // The prepared scene; mutable because render is const (Renderer's interface).
  mutable const scene::Scene* scene_ = nullptr;
  mutable std::unique_ptr<rays::RayScene> rays_;
  mutable std::size_t scenePreparations_ = 0;
};

}  // namespace tofsim::ir
