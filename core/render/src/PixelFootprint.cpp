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

// The doubles of one stage's filter (response_integrate.comp): prompt, tail
// ratio, tail weight, the re-emission matrix column by column, taps.
void packTaps(const physics::ResponseTaps& t, std::vector<double>& packed) {
  packed.insert(packed.end(), {t.prompt, t.tailRatio, t.tailWeight});
  for (int c = 0; c < 3; ++c) {
    packed.insert(packed.end(), {t.reemission[c].x, t.reemission[c].y, t.reemission[c].z});
  }
  packed.insert(packed.end(), t.taps.begin(), t.taps.end());
}

bool anyCascade(const std::vector<std::vector<physics::ResponseTaps>>& delayed) {
  return std::any_of(delayed.begin(), delayed.end(),
                     [](const std::vector<physics::ResponseTaps>& s) { return s.size() > 1; });
}

}  // namespace

PixelFootprint::PixelFootprint(std::size_t pixelsPerSegment, int32_t bins,
                               const std::vector<std::vector<physics::ResponseTaps>>& delayed)
    : bins_(bins),
      regionPixels_(pixelsPerSegment),
      classes_(delayed.size()),
      regions_(1 + classes_ + (anyCascade(delayed) ? 1 : 0)),
      // The plan counted every region (physics::responseBuffers) and kept
      // them within one storage block.
      diff_(regions_ * pixelsPerSegment * static_cast<std::size_t>(bins) * gpu::kChannels *
            sizeof(double)),
      written_((1 + classes_) * pixelsPerSegment * sizeof(uint32_t)),
      integrate_(gpu::makeProgram({{GL_COMPUTE_SHADER, "footprint_integrate.comp"}})) {
  integrate_.set("uBins", bins_);
  if (classes_ == 0) return;
  std::vector<double> packed;
  for (const std::vector<physics::ResponseTaps>& stages : delayed) {
    classTaps_.emplace_back();
    for (const physics::ResponseTaps& t : stages) {
      classTaps_.back().push_back({static_cast<uint32_t>(packed.size()), t.delay,
                                   static_cast<int32_t>(t.taps.size()), t.reemits()});
      packTaps(t, packed);
    }
  }
  taps_ = gl::Buffer(packed.size() * sizeof(double), packed.data());
  state_ = gl::Buffer(pixelsPerSegment * 16 * sizeof(double));
  response_ = gpu::makeProgram({{GL_COMPUTE_SHADER, "response_integrate.comp"}});
  response_.set("uBins", bins_);
}

void PixelFootprint::beginSegment(std::size_t pixels) {
  // The integration leaves the buffer zero; clearing here also covers a
  // render interrupted between a gather and its integration.
  diff_.clear();
  written_.clear();
  // Region 0 alone (the segment's pixels), or every region.
  const std::size_t bound = classes_ == 0 ? pixels : regions_ * regionPixels_;
  diff_.bindRange(GL_SHADER_STORAGE_BUFFER, gpu::kFootprint, 0,
                  bound * static_cast<std::size_t>(bins_) * gpu::kChannels * sizeof(double));
  written_.bindRange(GL_SHADER_STORAGE_BUFFER, gpu::kFootprintWritten, 0,
                     bound * sizeof(uint32_t));
}

void PixelFootprint::integrateInto(const gl::Buffer& volume, std::size_t pixels) {
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
  if (classes_ > 0) integrateClasses(pixels);
  TOFSIM_GL_CHECK("footprint integration");
}

void PixelFootprint::integrateClasses(std::size_t pixels) {
  taps_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kResponseTaps);
  state_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kResponseState);
  response_.use();
  response_.set("uPixelCount", static_cast<unsigned>(pixels));
  const auto scratch = static_cast<unsigned>((1 + classes_) * regionPixels_);
  for (std::size_t c = 0; c < classes_; ++c) {
    const auto own = static_cast<unsigned>((c + 1) * regionPixels_);
    response_.set("uRegion", own);
    const std::vector<StageTaps>& stages = classTaps_[c];
    // Stage k >= 1 reads what stage k - 1 wrote: the scratch region, then the
    // class's own (its bin integrals are read by then), in turn.
    for (std::size_t k = 0; k < stages.size(); ++k) {
      response_.set("uInput", k == 0 ? own : (k % 2 == 1 ? scratch : own));
      response_.set("uOutput", k % 2 == 0 ? scratch : own);
      response_.set("uFirstStage", k == 0 ? 1 : 0);
      response_.set("uLastStage", k + 1 == stages.size() ? 1 : 0);
      integrateStage(stages[k], pixels);
    }
  }
  // The classes' regions hold their bin integrals: zero for the next
  // gathers (region 0 is zero already: footprint_integrate.comp).
  diff_.clear();
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void PixelFootprint::integrateStage(const StageTaps& t, std::size_t pixels) {
  response_.set("uReemits", t.reemits ? 1 : 0);
  response_.set("uDelay", t.delay);
  response_.set("uTapCount", t.count);
  response_.set("uTapsOffset", t.offset);
  // Each bin is 1 + taps trips of the invocation's loops (llvmpipe's limit).
  const int32_t chunk = std::max(1, 20000 / (1 + t.count));
  for (int32_t first = 0; first < bins_; first += chunk) {
    response_.set("uFirstBin", first);
    response_.set("uBinCount", std::min(chunk, bins_ - first));
    gl::dispatchThreads(pixels, gpu::kWorkGroupSize);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  }
}

}  // namespace tofsim::render
