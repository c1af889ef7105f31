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

#include <memory>

#include "tofsim/capture/Renderer.h"
#include "tofsim/ir/IrBackend.h"

namespace tofsim::ir {

class IrRenderer : public capture::Renderer {
 public:
  explicit IrRenderer(std::unique_ptr<IrBackend> backend);

  std::string description() const override;
  /// Not thread-safe: the backend holds one render's state at a time.
  capture::RenderResult render(const capture::RenderJob& job, capture::SegmentSink& sink,
                               const capture::ProgressCallback& progress = {}) const override;

 private:
  std::unique_ptr<IrBackend> backend_;
};

}  // namespace tofsim::ir
