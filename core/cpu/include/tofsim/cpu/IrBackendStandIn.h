#pragma once
// STAND-IN, TO BE REPLACED by tofsim/ir/IrBackend.h (branch ir-driver, issue
// 12): a local copy of the agreed IR backend interface
// (/work/notes/ir-backend-interface.md), so the CPU backend can be written and
// tested before the driver exists. When core/ir lands, delete this file,
// include tofsim/ir/IrBackend.h and derive CpuBackend from ir::IrBackend.

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "tofsim/capture/RenderJob.h"

namespace tofsim::cpu {

struct DeviceLimits {
  int32_t maxImageSide = 0;          ///< largest G-buffer / RSM / shadow-map side
  std::size_t maxBufferBytes = 0;    ///< largest single buffer
  std::size_t maxPixelsPerPass = 0;  ///< most pixels one gather call may cover
};

struct Vpl {               ///< layout = struct Vpl in shaders/vpl.glsl (std430)
  glm::vec4 positionPath;  ///< xyz world, w = optical path light -> VPL, m (eta included)
  glm::vec4 normal;        ///< xyz unit, lit side
  glm::vec4 flux;          ///< rgb albedo * Phi / pi, W/sr
};

/// Guarantees (as the real interface states them): the same job gives the same
/// bytes whatever the thread count or the segment / batch plan; every
/// (pixel, bin) has one writer, adding VPLs in increasing index; off-axis
/// sums are added in pixel order; gathers touch only the current segment.
class IrBackendStandIn {
 public:
  virtual ~IrBackendStandIn() = default;
  virtual std::string description() const = 0;
  virtual DeviceLimits limits() const = 0;
  virtual std::vector<float> prepareSurfaces(const capture::RenderJob& job) = 0;
  virtual std::vector<Vpl> generateVpls(const capture::RenderJob& job) = 0;
  virtual void setVpls(const std::vector<Vpl>& vpls) = 0;
  virtual std::size_t fixedBytes() const = 0;
  virtual std::size_t visibilityBytesPerVpl() const = 0;
  virtual void allocate(std::size_t pixelsPerSegment, std::size_t vplsPerBatch) = 0;
  virtual void buildVisibility(std::size_t firstVpl, std::size_t count) = 0;
  virtual void beginSegment(std::size_t firstPixel, std::size_t count) = 0;
  virtual void gatherDirect() = 0;
  virtual void gatherIndirect(std::size_t firstVpl, std::size_t count) = 0;
  virtual void readSegment(float* direct, float* indirect, AxisLoss& offAxis) = 0;
};

}  // namespace tofsim::cpu
