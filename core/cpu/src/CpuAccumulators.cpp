// The CPU backend's per-segment accumulators (CpuBackend.h): their
// allocation, the per-pixel integrate step (the instant class's footprint
// buffer, then the delayed response classes, core/physics/temporal_response.md)
// and the read-back that copies each pixel out and zeroes it while in cache.
#include "tofsim/cpu/CpuBackend.h"

#include <algorithm>
#include <utility>

#include "CpuIsm.h"
#include "FootprintDeposit.h"
#include "GatherKernel.h"
#include "GatherTiles.h"
#include "ParallelFor.h"
#include "ResponseClasses.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/physics/FootprintBuffer.h"
#include "tofsim/physics/TemporalResponse.h"

namespace tofsim::cpu {

void CpuBackend::allocate(std::size_t pixelsPerSegment, std::size_t vplsPerBatch) {
  finishSurfaces();
  pixelsPerSegment_ = pixelsPerSegment;
  const std::size_t floats = pixelsPerSegment * job_.settings.time.bins * kChannels;
  const std::size_t footprintFloats = job_.settings.pixel_footprint ? floats : 0;
  // Fresh buffers come zero from the kernel; buffers of the same size (the
  // next render of a sequence) are kept, zeroed where an unfinished segment
  // left something.
  if (direct_.size() != floats || footprint_.size() != footprintFloats) {
    direct_ = util::ZeroedBuffer<float>(floats);
    indirect_ = util::ZeroedBuffer<float>(floats);
    footprint_ = util::ZeroedBuffer<double>(footprintFloats);  // the plan counted it
    footprintBins_.assign(pixelsPerSegment, FootprintBins{});
  } else if (!accumulatorsZero_) {
    clearAccumulators(pixelsPerSegment);
  }
  if (responseClasses_.delayed() || !responses_->empty()) {
    responses_->configure(physics::classStages(responseClasses_, job_.settings.time.bin_width_s),
                          pixelsPerSegment, job_.settings.time.bins);
  }
  // The VPLs' light scattered by the medium into the camera rays: zeroed by
  // moveOut as it adds it to the indirect light (or here, when a segment was
  // left unfinished).
  const std::size_t mediumFloats = mediumVpls_ ? floats : 0;
  if (mediumIndirect_.size() != mediumFloats) {
    mediumIndirect_ = util::ZeroedBuffer<float>(mediumFloats);
  } else {
    std::fill_n(mediumIndirect_.data(), mediumFloats, 0.0f);
  }
  mediumOutside_.assign(mediumVpls_ ? pixelsPerSegment : 0, physics::OffAxisSums{});
  accumulatorsZero_ = true;
  outside_.assign(pixelsPerSegment, physics::OffAxisSums{});
  segmentSurfaces_.resize(pixelsPerSegment * maxSamplesPerPixel());
  segmentLit_.resize(pixelsPerSegment * maxSamplesPerPixel());
  segmentFirstSample_.resize(pixelsPerSegment + 1);
  if (ism_) ism_->allocate(vplsPerBatch);
}

double* CpuBackend::footprintOf(std::size_t i, const glm::vec3& kernel) {
  const int32_t bins = job_.settings.time.bins;
  widenToWideKernel(kernel, bins, footprintBins_[i].first, footprintBins_[i].last);
  return footprint_.data() + i * static_cast<std::size_t>(bins) * kChannels;
}

void CpuBackend::setResponseClasses(const physics::ResponseClassTable& classes) {
  responseClasses_ = classes;
}

void CpuBackend::integratePixel(std::size_t i, float* histogram) {
  FootprintBins& written = footprintBins_[i];
  if (written.first <= written.last) {
    const int32_t bins = job_.settings.time.bins;
    const std::size_t first = static_cast<std::size_t>(written.first) * kChannels;
    double* diff = footprint_.data() + i * static_cast<std::size_t>(bins) * kChannels;
    // The entries before `first` are zero: so are both running sums there, and
    // adding +0.0f leaves a histogram bin's bits as they are (a sum of floats
    // from +0 is never -0), so the sums start at `first`.
    physics::integrateFootprint(diff + first, bins - written.first, histogram + first);
    // While in cache: zero for the next wide kernel.
    std::fill(diff + first, diff + (static_cast<std::size_t>(written.last) + 1) * kChannels, 0.0);
    written = FootprintBins{};
  }
  // The instant class's light is in; the delayed classes' (none today) after it.
  if (!responses_->empty()) responses_->integrateInto(i, histogram, outside_[i]);
}

void CpuBackend::clearAccumulators(std::size_t pixels) {
  const std::size_t stride = static_cast<std::size_t>(job_.settings.time.bins) * kChannels;
  std::fill_n(direct_.data(), pixels * stride, 0.0f);
  std::fill_n(indirect_.data(), pixels * stride, 0.0f);
  std::fill_n(mediumIndirect_.data(), mediumIndirect_.size() > 0 ? pixels * stride : 0, 0.0f);
  std::fill(mediumOutside_.begin(), mediumOutside_.end(), physics::OffAxisSums{});
  for (std::size_t i = 0; i < pixels && footprint_.size() > 0; ++i) {
    const FootprintBins written = footprintBins_[i];
    if (written.first <= written.last) {
      std::fill(
          footprint_.data() + i * stride + static_cast<std::size_t>(written.first) * kChannels,
          footprint_.data() + i * stride + (static_cast<std::size_t>(written.last) + 1) * kChannels,
          0.0);
    }
    footprintBins_[i] = FootprintBins{};
  }
  responses_->clear();
}

void CpuBackend::moveOut(float* from, float* to, bool integrateFootprints, float* medium) {
  const std::size_t tiles = (pixelCount_ + kTilePixels - 1) / kTilePixels;
  const std::size_t stride = static_cast<std::size_t>(job_.settings.time.bins) * kChannels;
  // Per pixel while its histogram is in cache: the wide footprint kernels
  // summed in (integratePixel clears each footprint buffer it read), copied
  // out, zeroed for the next bounce or segment.
  parallelFor(tiles, threads_, [&](std::size_t tile) {
    const std::size_t end = std::min(pixelCount_, (tile + 1) * kTilePixels);
    for (std::size_t i = tile * kTilePixels; i < end; ++i) {
      float* histogram = &from[i * stride];
      if (integrateFootprints) integratePixel(i, histogram);
      if (medium != nullptr) {  // the VPLs' light in the medium, after the surfaces'
        float* add = medium + i * stride;
        for (std::size_t j = 0; j < stride; ++j) histogram[j] += add[j];
        std::fill_n(add, stride, 0.0f);
      }
      std::copy_n(histogram, stride, to + i * stride);
      std::fill_n(histogram, stride, 0.0f);
    }
  });
}

void CpuBackend::takeIndirect(float* indirect) {
  moveOut(indirect_.data(), indirect, job_.settings.pixel_footprint || !responses_->empty(),
          mediumVpls_ ? mediumIndirect_.data() : nullptr);
}

void CpuBackend::readSegment(float* direct, float* indirect, AxisLoss& offAxis) {
  // The direct gather integrated its footprints itself; the indirect gathers'
  // wide kernels, added after every batch, are summed once per pixel here.
  moveOut(direct_.data(), direct, false);
  moveOut(indirect_.data(), indirect, job_.settings.pixel_footprint || !responses_->empty(),
          mediumVpls_ ? mediumIndirect_.data() : nullptr);
  accumulatorsZero_ = true;
  for (std::size_t i = 0; i < pixelCount_ && mediumVpls_; ++i) {
    outside_[i].before += mediumOutside_[i].before;
    outside_[i].after += mediumOutside_[i].after;
    mediumOutside_[i] = physics::OffAxisSums{};
  }
  for (std::size_t i = 0; i < pixelCount_; ++i) {
    offAxis.before += outside_[i].before;
    offAxis.after += outside_[i].after;
  }
}

}  // namespace tofsim::cpu
