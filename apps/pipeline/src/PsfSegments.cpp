#include "tofsim/pipeline/PsfSegments.h"

#include <algorithm>

#include "tofsim/optics/PsfConvolution.h"
#include "tofsim/pipeline/FiniteSegments.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {
constexpr double kMiB = 1024.0 * 1024.0;

std::string mebibytes(double bytes) {
  const long long tenths = static_cast<long long>(bytes / kMiB * 10.0 + 0.5);
  return std::to_string(tenths / 10) + "." + std::to_string(tenths % 10) + " MiB";
}
}  // namespace

std::size_t psfHeldBytes(int32_t width, int32_t height, int32_t bins, std::size_t components) {
  return components * static_cast<std::size_t>(width) * height * bins * capture::kChannels *
         sizeof(float);
}

void checkPsfFits(const config::RunConfig& config, int32_t width, int32_t height, int32_t bins,
                  std::size_t bounces) {
  if (!config.camera.psf) return;
  const std::size_t components = 2 + bounces;
  const std::size_t held = psfHeldBytes(width, height, bins, components);
  const auto budget = static_cast<double>(config.render.memory_budget_bytes);
  if (static_cast<double>(held) <= budget) return;
  throw InputError(config.camera.psf->at, "camera.psf",
                   "the PSF holds the whole volume in memory: " + std::to_string(components) +
                       " components (direct, indirect, the bounces read) of " +
                       std::to_string(height) + " x " + std::to_string(width) + " x " +
                       std::to_string(bins) + " bins x 3 floats, " + mebibytes(double(held)) +
                       ", more than render.memory_budget (" + mebibytes(budget) +
                       "); raise render.memory_budget, or lower camera.resolution or time.bins");
}

PsfSegments::PsfSegments(capture::SegmentSink& next, int32_t width, int32_t height, int32_t bins,
                         optics::PsfKernel kernel, int threads)
    : next_(next),
      width_(width),
      height_(height),
      bins_(bins),
      kernel_(std::move(kernel)),
      threads_(threads) {}

void PsfSegments::consume(const capture::Segment& segment) {
  const std::size_t perPixel = static_cast<std::size_t>(bins_) * capture::kChannels;
  const std::size_t pixels = static_cast<std::size_t>(width_) * height_;
  if (names_.empty()) {
    for (const capture::SegmentComponent& c : segment.components) {
      names_.push_back(c.name);
      volumes_.emplace_back(c.name == kTotal ? 0 : pixels * perPixel);
    }
  }
  TOFSIM_CHECK_EQ(segment.components.size(), names_.size());
  TOFSIM_CHECK_EQ(segment.firstPixel, gathered_);  // in order, each pixel once
  for (std::size_t i = 0; i < names_.size(); ++i) {
    TOFSIM_CHECK(segment.components[i].name == names_[i]);
    if (names_[i] == kTotal) continue;
    const float* from = segment.components[i].values;
    std::copy(from, from + segment.pixelCount * perPixel,
              volumes_[i].begin() + static_cast<std::ptrdiff_t>(segment.firstPixel * perPixel));
  }
  segments_.emplace_back(segment.firstPixel, segment.pixelCount);
  gathered_ += segment.pixelCount;
  if (gathered_ == pixels) convolveAndSend();
}

void PsfSegments::convolveAndSend() {
  const std::size_t perPixel = static_cast<std::size_t>(bins_) * capture::kChannels;
  // Plane t C + c of the (H, W, T, C) volume: bin t, channel c.
  const optics::PlaneLayout layout{width_, height_, perPixel, 1};
  const float* direct = nullptr;
  const float* indirect = nullptr;
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == kTotal) continue;
    optics::applyPsf(kernel_, volumes_[i].data(), perPixel, layout,
                     {optics::PsfMethod::Auto, threads_});
    // A kernel >= 0 on light >= 0 gives light >= 0: what the FFT leaves
    // below 0 is its round-off, which a saved volume must not hold
    // (SavedVolume.cpp refuses negative radiance).
    for (float& v : volumes_[i]) v = std::max(v, 0.0f);
    if (names_[i] == capture::kDirect) direct = volumes_[i].data();
    if (names_[i] == capture::kIndirect) indirect = volumes_[i].data();
  }
  std::vector<float> total;
  for (const auto& [first, count] : segments_) {
    const std::size_t offset = first * perPixel, floats = count * perPixel;
    capture::Segment out{first, count, {}};
    for (std::size_t i = 0; i < names_.size(); ++i) {
      if (names_[i] != kTotal) {
        out.components.push_back({names_[i], volumes_[i].data() + offset});
        continue;
      }
      // As FiniteSegments adds it: direct + indirect in float.
      TOFSIM_CHECK(direct != nullptr && indirect != nullptr);
      total.resize(floats);
      for (std::size_t k = 0; k < floats; ++k) total[k] = direct[offset + k] + indirect[offset + k];
      zeroNonFinite(total.data(), floats);  // as there: two finite floats can overflow
      out.components.push_back({kTotal, total.data()});
    }
    next_.consume(out);
  }
  volumes_ = {};  // the outputs written next need the memory more
}

}  // namespace tofsim::pipeline
