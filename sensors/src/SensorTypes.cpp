// The sensor descriptors of SensorType.h, one block per model.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "SpadCrosstalk.h"
#include "SpadFlux.h"
#include "tofsim/sensors/CwTofPresets.h"
#include "tofsim/sensors/SensorType.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
// A handful of images and PNG pictures beside each sensor's arrays (float32
// image + 8-bit RGB picture per pixel), as a bound for the output estimate.
std::uintmax_t imageBytes(int32_t width, int32_t height) {
  return 8 * static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height) * (4 + 3);
}
}  // namespace

std::string timeKernelProblem(const TimeKernelUse& k) {
  const double reach = kernelReachBins(k.support, k.bin_width);
  if (reach <= kMaxKernelReachBins) return "";
  char text[200];
  std::snprintf(text, sizeof text,
                "reaches %.3g bins of %.3g %s (%.3g %s) from zero delay; a blur kernel reaches at "
                "most %.0f bins",
                reach, k.bin_width, k.unit, std::max(std::fabs(k.support.lo), std::fabs(k.support.hi)),
                k.unit, kMaxKernelReachBins);
  return text;
}

namespace {
// The config checks each kernel where it reads the keys; a volume on another
// axis (`tofsim sense`, the Python module) is checked again where it opens.
template <typename Params>
void checkTimeKernels(const Params& p, const TimeAxis& axis) {
  for (const TimeKernelUse& k : SensorType<Params>::timeKernels(p, axis)) {
    const std::string problem = timeKernelProblem(k);
    if (!problem.empty()) {
      throw InputError(std::string(SensorType<Params>::name) + " sensor `" + k.key + "`: " + problem);
    }
  }
}
}  // namespace

// --- streak --------------------------------------------------------------------
std::unique_ptr<SensorStream> SensorType<StreakParams>::open(const StreakParams& p,
                                                             const VolumeShape& shape,
                                                             const StreamOptions& options) {
  checkTimeKernels(p, shape.axis);
  return openStreak(p, shape, options);
}
std::vector<std::string> SensorType<StreakParams>::warnings(const StreakParams&, const VolumeShape&,
                                                            const Image*) {
  return {};
}
std::uintmax_t SensorType<StreakParams>::outputBytes(const StreakParams& p, int32_t width,
                                                     int32_t height, const TimeAxis& render) {
  const std::uintmax_t bins = resolveBins(p.bins, render).bins;
  const std::uintmax_t rows = p.rows.empty() ? static_cast<std::uintmax_t>(height) : p.rows.size();
  return rows * static_cast<std::uintmax_t>(width) * bins * (4 + 3) + imageBytes(width, height);
}
std::optional<InstrumentWindow> SensorType<StreakParams>::window(const StreakParams& p) {
  return InstrumentWindow{p.common, p.bins, p.rows};
}
std::vector<TimeKernelUse> SensorType<StreakParams>::timeKernels(const StreakParams& p,
                                                                 const TimeAxis& render) {
  // StreakStream's: a Gaussian in time on its bins, one along x on pixels.
  return {{"time_fwhm", gaussianTailSupport(fwhmToSigma(p.time_fwhm_s), 0.0, 0.0),
           resolveBins(p.bins, render).bin_width_s, "s"},
          {"spatial_fwhm", gaussianTailSupport(fwhmToSigma(p.spatial_fwhm_px), 0.0, 0.0), 1.0,
           "px"}};
}

// --- spad ----------------------------------------------------------------------
std::unique_ptr<SensorStream> SensorType<SpadParams>::open(const SpadParams& p,
                                                           const VolumeShape& shape,
                                                           const StreamOptions& options) {
  checkTimeKernels(p, shape.axis);
  return openSpad(p, shape, options);
}
std::vector<std::string> SensorType<SpadParams>::warnings(const SpadParams& p,
                                                          const VolumeShape& shape, const Image*) {
  const TimeAxis& render = shape.axis;
  std::vector<std::string> out;
  const auto ps = [](double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g ps", s * 1e12);
    return std::string(text);
  };
  // A render bin's light is spread evenly over the TDC bins it covers
  // (resampleEnergy), so bins coarser than the TDC's draw flat steps, the
  // render's width each, where the instrument would resolve the pulse.
  const double tdcWidth = resolveBins(p.bins, render).bin_width_s;
  if (render.bin_width_s > tdcWidth * (1.0 + 1e-9)) {
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%.3g", render.bin_width_s / tdcWidth);
    out.push_back(
        "the render's bins (" + ps(render.bin_width_s) + ") are coarser than the TDC's (" +
        ps(tdcWidth) + "): the histogram shows flat steps " + ratio +
        " TDC bins wide; render with time.bin_width <= " + ps(tdcWidth) + " to resolve them");
  }
  if (p.irf.present()) {
    // The part of the response the window cannot hold is folded back into it
    // (convolveConserving), so the histogram's shape misleads.
    const TimeAxis axis = resolveBins(p.bins, render);
    const double irfWidth = static_cast<double>(p.irf.values.size()) * p.irf.sample_width_s;
    const double window = axis.bins * axis.bin_width_s;
    if (irfWidth > window) {
      out.push_back("the IRF spans " + ps(irfWidth) + ", wider than the TDC window of " +
                    ps(window) + ": light it moves outside the window is folded back in (" +
                    p.irf.file + ")");
    }
  }
  return out;
}
std::uintmax_t SensorType<SpadParams>::outputBytes(const SpadParams& p, int32_t width,
                                                   int32_t height, const TimeAxis& render) {
  const std::uintmax_t bins = resolveBins(p.bins, render).bins;
  const auto pixels = static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height);
  // Gated frames: counts and flux per gate position.
  const std::uintmax_t gated =
      p.gated_frames > 0 ? 2 * static_cast<std::uintmax_t>(p.gate_positions) : 0;
  return pixels * (bins + gated) * 4 + imageBytes(width, height);
}
std::optional<InstrumentWindow> SensorType<SpadParams>::window(const SpadParams& p) {
  return InstrumentWindow{p.common, p.bins, {}};
}
std::vector<TimeKernelUse> SensorType<SpadParams>::timeKernels(const SpadParams& p,
                                                               const TimeAxis& render) {
  const double binWidth_s = resolveBins(p.bins, render).bin_width_s;
  const KernelSupport support = detail::spadKernelSupport(p);
  // The key named is the one that widens the kernel most: the tail reaches
  // past the Gaussian's 6 sigma by its 14 time constants.
  const char* key = p.irf.present() ? "irf"
                    : support.hi + support.lo > -support.lo ? "jitter_tail"
                    : p.jitter_fwhm_s >= p.pulse_fwhm_s     ? "jitter_fwhm"
                                                            : "pulse_fwhm";
  return {{key, support, binWidth_s, "s"},
          {"crosstalk_delay", detail::crosstalkDelaySupport(p.crosstalk_delay_s), binWidth_s, "s"}};
}

// --- cwtof ---------------------------------------------------------------------
std::unique_ptr<SensorStream> SensorType<CwTofParams>::open(const CwTofParams& p,
                                                            const VolumeShape& shape,
                                                            const StreamOptions& options) {
  return openCwTof(p, shape, options);
}
std::vector<std::string> SensorType<CwTofParams>::warnings(const CwTofParams& p,
                                                           const VolumeShape& shape,
                                                           const Image* groundTruthDepth_m) {
  std::vector<std::string> out = cwtofWarnings(p, shape.axis, groundTruthDepth_m);
  for (std::string& w : presetImageWarnings(findCwTofPreset(p.preset), shape.width, shape.height))
    out.push_back(std::move(w));
  return out;
}
std::uintmax_t SensorType<CwTofParams>::outputBytes(const CwTofParams& p, int32_t width,
                                                    int32_t height, const TimeAxis&) {
  const auto pixels = static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height);
  // The raw images and the phase array, then four images with their
  // pictures per frequency (phase, amplitude, depth, multipath error).
  const std::uintmax_t F = p.frequencies_Hz.size();
  const auto steps = static_cast<std::uintmax_t>(p.phase_steps);
  // By order: up to 9 orders (render.indirect.bounces' limit 8, plus the
  // direct light), an array plane and a picture each.
  const std::uintmax_t orders = p.multipath_by_order ? 9 : 0;
  // And the wiggling sweep, F x kWigglingSweepPoints floats.
  return F * (steps + 1) * pixels * 4 + F * 4 * pixels * (4 + 3) + orders * pixels * (4 + 3) +
         F * kWigglingSweepPoints * 4 + imageBytes(width, height);
}
std::optional<InstrumentWindow> SensorType<CwTofParams>::window(const CwTofParams&) {
  return std::nullopt;
}
std::vector<TimeKernelUse> SensorType<CwTofParams>::timeKernels(const CwTofParams&,
                                                                const TimeAxis&) {
  return {};
}

// --- apd -----------------------------------------------------------------------
std::unique_ptr<SensorStream> SensorType<ApdParams>::open(const ApdParams& p,
                                                          const VolumeShape& shape,
                                                          const StreamOptions& options) {
  checkTimeKernels(p, shape.axis);
  return openApd(p, shape, options);
}
std::vector<std::string> SensorType<ApdParams>::warnings(const ApdParams&, const VolumeShape&,
                                                         const Image*) {
  return {};
}
std::uintmax_t SensorType<ApdParams>::outputBytes(const ApdParams& p, int32_t width,
                                                  int32_t height, const TimeAxis& render) {
  const auto pixels = static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height);
  const std::uintmax_t bins = p.output_waveforms ? resolveBins(p.bins, render).bins : 0;
  return pixels * (bins + 2 * static_cast<std::uintmax_t>(p.max_returns)) * 4 +
         imageBytes(width, height);
}
std::optional<InstrumentWindow> SensorType<ApdParams>::window(const ApdParams& p) {
  return InstrumentWindow{p.common, p.bins, {}};
}
std::vector<TimeKernelUse> SensorType<ApdParams>::timeKernels(const ApdParams& p,
                                                              const TimeAxis& render) {
  const double dt = resolveBins(p.bins, render).bin_width_s;
  return {{"pulse_fwhm", gaussianTailSupport(fwhmToSigma(p.pulse_fwhm_s), 0.0, 0.0), dt, "s"},
          {"bandwidth", gaussianTailSupport(apdFilterSigma_s(p.bandwidth_Hz), 0.0, 0.0), dt, "s"}};
}

}  // namespace tofsim::sensors
