#include "SpadGatedFrames.h"

#include <cmath>
#include <string>

#include "PeakDepth.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

namespace {
constexpr uint32_t kGatedFramesTag = 0x4746;  // "GF": its own stream, spad_counts' is unchanged
}  // namespace

double clipCount(double count, int32_t bits) {
  if (bits <= 0) return count;
  return std::min(count, std::ldexp(1.0, bits) - 1.0);
}

void gatedFluxes(const SpadParams& p, const SpadGate& gate, const TdcBins& bins,
                 const std::vector<double>& flux, double skew_s, std::vector<double>& lambda) {
  lambda.resize(static_cast<std::size_t>(p.gate_positions));
  for (int32_t k = 0; k < p.gate_positions; ++k) {
    lambda[k] = gatedFlux(gate.shifted(skew_s + k * p.gate_step_s), bins, flux);
  }
}

SpadGatedFrames::SpadGatedFrames(const SpadParams& p, const VolumeShape& shape,
                                 const StreamOptions& options)
    : p_(p),
      options_(options),
      bins_(tdcBins(p, resolveBins(p.bins, shape.axis))),
      gate_(spadGate(p)),
      positions_(p.gated_frames > 0 ? static_cast<std::size_t>(p.gate_positions) : 0) {
  if (!active()) return;
  TOFSIM_CHECK(p.pulses_per_frame >= 1 && p.gate_positions >= 1 && p.gate_width_s > 0.0);
  const std::string frames = std::to_string(p.gated_frames) + " gated 1-bit frames of " +
                             std::to_string(p.pulses_per_frame) + " pulses";
  open(counts_, "spad_gated_counts", "counts",
       "SPAD frames (of " + frames + ") whose latch fired, per gate position", shape);
  open(flux_, "spad_gated_flux", "detections / pulse",
       "SPAD detections per pulse inside the gate, -ln(1 - c / N_f) / M from " + frames +
           " (all frames fired: ln(N_f + 1) / M)",
       shape);
}

void SpadGatedFrames::open(Array& a, const char* name, const char* unit,
                           const std::string& description, const VolumeShape& shape) {
  a.out.name = name;
  a.out.kind = SensorOutput::Kind::Array;
  a.out.shape = {shape.height, shape.width, static_cast<int64_t>(positions_)};
  a.out.axes = {"y", "x", "gate"};
  a.out.unit = unit;
  a.out.description = description;
  a.out.attributes = {{"gated_frames", static_cast<double>(p_.gated_frames)},
                      {"pulses_per_frame", static_cast<double>(p_.pulses_per_frame)},
                      {"gate_start_s", p_.gate_start_s},
                      {"gate_width_s", p_.gate_width_s},
                      {"gate_step_s", p_.gate_step_s}};
  if (options_.arrays) {
    a.writer = options_.arrays->open(a.out.name, a.out.shape);
    a.out.streamed = true;
  } else {
    a.out.data.resize(shape.pixelCount() * positions_);
  }
}

void SpadGatedFrames::beginSpan(std::size_t firstPixel, std::size_t pixelCount) {
  if (!active()) return;
  firstPixel_ = firstPixel;
  for (Array* a : {&counts_, &flux_}) {
    if (a->writer) {
      a->chunk.resize(pixelCount * positions_);
      a->span = a->chunk.data();
    } else {
      a->span = a->out.data.data() + firstPixel * positions_;
    }
  }
}

void SpadGatedFrames::pixel(std::size_t px, const std::vector<double>& flux, double skew_s,
                            std::vector<double>& lambda) const {
  if (!active()) return;
  gatedFluxes(p_, gate_, bins_, flux, skew_s, lambda);
  Rng rng(options_.seed, pixelStream(kGatedFramesTag, px));
  const auto frames = static_cast<uint64_t>(p_.gated_frames);
  const auto M = static_cast<double>(p_.pulses_per_frame);
  const std::size_t at = (px - firstPixel_) * positions_;
  for (std::size_t k = 0; k < positions_; ++k) {
    const double fire = -std::expm1(-M * lambda[k]);
    const double c = clipCount(static_cast<double>(rng.binomial(frames, fire)), p_.counter_bits);
    counts_.span[at + k] = static_cast<float>(c);
    flux_.span[at + k] = static_cast<float>(coatesBinFlux(c, static_cast<double>(frames)) / M);
  }
}

void SpadGatedFrames::endSpan() {
  for (Array* a : {&counts_, &flux_}) {
    if (a->writer) a->writer->append(a->chunk.data(), a->chunk.size());
  }
}

void SpadGatedFrames::finish(std::vector<SensorOutput>& outputs) {
  if (!active()) return;
  for (Array* a : {&counts_, &flux_}) {
    if (a->writer) a->writer->close();
    outputs.push_back(std::move(a->out));
  }
}

}  // namespace tofsim::sensors::detail
