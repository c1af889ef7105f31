#pragma once
// The lens's PSF (config::PsfConfig, optics::PsfKernel) applied to the
// cleaned segments (behind FiniteSegments, so no NaN spreads): a PSF mixes
// the pixels of one time bin, so it cannot act on a run of pixels. Each
// component but the total (direct, indirect, the bounces read) is gathered
// whole; once the last pixel has come, every time bin and channel of each
// is convolved (optics::applyPsf, light keeps its delay), the total is
// direct + indirect again in float, so the component files still add up to
// transient.npy, and the segments go on as they came. The volume is held in
// host memory: psfHeldBytes, checked against render.memory_budget
// (checkPsfFits) before the render starts.

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "tofsim/capture/SegmentSink.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/optics/PsfKernel.h"

namespace tofsim::pipeline {

/// Bytes PsfSegments holds for `components` gathered components of a
/// width x height x bins x kChannels float volume.
std::size_t psfHeldBytes(int32_t width, int32_t height, int32_t bins, std::size_t components);

/// Throws InputError at camera.psf, naming render.memory_budget, when the
/// PSF's volume (direct, indirect and `bounces` bounce components) would
/// not fit the budget.
void checkPsfFits(const config::RunConfig& config, int32_t width, int32_t height, int32_t bins,
                  std::size_t bounces);

class PsfSegments : public capture::SegmentSink {
 public:
  /// threads: over the planes (0 = every core); the bytes do not depend on it.
  PsfSegments(capture::SegmentSink& next, int32_t width, int32_t height, int32_t bins,
              optics::PsfKernel kernel, int threads);
  void consume(const capture::Segment& segment) override;

 private:
  void convolveAndSend();

  capture::SegmentSink& next_;
  int32_t width_, height_, bins_;
  optics::PsfKernel kernel_;
  int threads_;
  std::vector<std::string_view> names_;      ///< the components, in the segments' order
  std::vector<std::vector<float>> volumes_;  ///< per name; empty for the total
  std::vector<std::pair<std::size_t, std::size_t>> segments_;  ///< first pixel, count
  std::size_t gathered_ = 0;                                   ///< pixels
};

}  // namespace tofsim::pipeline
