#include "PixelFootprint.h"

#include <algorithm>

#include "GpuContract.h"
#include "tofsim/gl/Check.h"
#include "tofsim/gl/Compute.h"

namespace tofsim::render {

namespace {

// Bins one integration dispatch covers: llvmpipe ends an invocation's loops
// after 65535 trips in total (IndirectLight.cpp), and each bin is a trip for
// each of the 3 channels; a third of the limit, as the gathers keep.
constexpr int32_t kBinsPerDispatch = 20000 / gpu::kChannels;

}  // namespace

PixelFootprint::PixelFootprint(std::size_t pixelsPerSegment, int32_t bins)
    : bins_(bins),
      diff_(pixelsPerSegment * static_cast<std::size_t>(bins) * gpu::kChannels * sizeof(double)),
      written_(pixelsPerSegment * sizeof(uint32_t)),
      integrate_(gpu::makeProgram({{GL_COMPUTE_SHADER, "footprint_integrate.comp"}})) {
  integrate_.set("uBins", bins_);
}

void PixelFootprint::beginSegment(std::size_t pixels) {
  // The integration leaves the buffer zero; clearing here also covers a
  // render interrupted between a gather and its integration.
  diff_.clear();
  written_.clear();
  diff_.bindRange(GL_SHADER_STORAGE_BUFFER, gpu::kFootprint, 0,
                  pixels * static_cast<std::size_t>(bins_) * gpu::kChannels * sizeof(double));
  written_.bindRange(GL_SHADER_STORAGE_BUFFER, gpu::kFootprintWritten, 0,
                     pixels * sizeof(uint32_t));
}

void PixelFootprint::integrateInto(const gl::Buffer& volume, std::size_t pixels) const {
  volume.bindRange(GL_SHADER_STORAGE_BUFFER, gpu::kFootprintVolume, 0,
                   pixels * static_cast<std::size_t>(bins_) * gpu::kChannels * sizeof(float));
  integrate_.use();
  integrate_.set("uPixelCount", static_cast<unsigned>(pixels));
  // Chunks in increasing bin order; the running sums wait in the buffer.
  for (int32_t first = 0; first < bins_; first += kBinsPerDispatch) {
    integrate_.set("uFirstBin", first);
    integrate_.set("uBinCount", std::min(kBinsPerDispatch, bins_ - first));
    gl::dispatchThreads(pixels, gpu::kWorkGroupSize);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  }
  TOFSIM_GL_CHECK("footprint integration");
}

}  // namespace tofsim::render
