#pragma once
// Drives the CPU backend the way the IR driver does (prepareSurfaces,
// generateVpls, setVpls, allocate, then per segment beginSegment,
// gatherDirect, per batch buildVisibility + gatherIndirect, readSegment),
// with a chosen plan, and collects the volume. Stands in for the driver of
// core/ir until that lands; it holds no physics of its own.

#include <algorithm>
#include <vector>

#include "tofsim/capture/DirectLightView.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"

namespace tofsim::test {

struct CpuRender {
  capture::VolumeCollector volume;
  AxisLoss offAxis;
  std::size_t vpls = 0;
};

/// 0 for pixelsPerSegment / vplsPerBatch: all in one.
inline CpuRender renderOnCpu(const capture::RenderJob& job, const cpu::CpuBackendOptions& options,
                             std::size_t pixelsPerSegment = 0, std::size_t vplsPerBatch = 0) {
  const int channels = 3;
  CpuRender out{
      capture::VolumeCollector(job.camera.width, job.camera.height, job.settings.time, channels),
      {},
      0};
  cpu::CpuBackend backend(options);
  const std::vector<float> positions = backend.prepareSurfaces(job);
  const std::vector<cpu::Vpl> vpls = backend.generateVpls(job);
  backend.setVpls(vpls);
  out.vpls = vpls.size();
  const std::size_t pixels = static_cast<std::size_t>(job.camera.width) * job.camera.height;
  if (pixelsPerSegment == 0) pixelsPerSegment = pixels;
  if (vplsPerBatch == 0) vplsPerBatch = std::max<std::size_t>(vpls.size(), 1);
  backend.allocate(pixelsPerSegment, vplsPerBatch);
  const capture::DirectLightView lightView = capture::directLightView(job, positions);
  const std::size_t floatsPerPixel = static_cast<std::size_t>(job.settings.time.bins) * channels;
  std::vector<float> direct(pixelsPerSegment * floatsPerPixel),
      indirect(pixelsPerSegment * floatsPerPixel);
  const std::size_t batches = (vpls.size() + vplsPerBatch - 1) / vplsPerBatch;
  for (std::size_t first = 0; first < pixels; first += pixelsPerSegment) {
    const std::size_t count = std::min(pixelsPerSegment, pixels - first);
    backend.beginSegment(first, count);
    backend.gatherDirect();
    for (std::size_t b = 0; b < batches; ++b) {
      const std::size_t firstVpl = b * vplsPerBatch;
      const std::size_t n = std::min(vplsPerBatch, vpls.size() - firstVpl);
      // A single batch is built once for the whole render, as the driver does.
      if (batches > 1 || first == 0) backend.buildVisibility(firstVpl, n);
      backend.gatherIndirect(firstVpl, n);
    }
    backend.readSegment(direct.data(), indirect.data(), out.offAxis);
    out.offAxis += lightView.addTo(first, count, job.settings.time, channels, direct.data());
    capture::Segment segment;
    segment.firstPixel = first;
    segment.pixelCount = count;
    segment.direct = direct.data();
    segment.indirect = indirect.data();
    out.volume.consume(segment);
  }
  return out;
}

}  // namespace tofsim::test
