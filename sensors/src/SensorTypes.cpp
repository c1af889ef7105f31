// The sensor descriptors of SensorType.h, one block per model.
#include <cstdio>
#include <string>

#include "tofsim/sensors/CwTofPresets.h"
#include "tofsim/sensors/SensorType.h"

namespace tofsim::sensors {

namespace {
// A handful of images and PNG pictures beside each sensor's arrays (float32
// image + 8-bit RGB picture per pixel), as a bound for the output estimate.
std::uintmax_t imageBytes(int32_t width, int32_t height) {
  return 8 * static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height) * (4 + 3);
}
}  // namespace

// --- streak --------------------------------------------------------------------
std::unique_ptr<SensorStream> SensorType<StreakParams>::open(const StreakParams& p,
                                                             const VolumeShape& shape,
                                                             const StreamOptions& options) {
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

// --- spad ----------------------------------------------------------------------
std::unique_ptr<SensorStream> SensorType<SpadParams>::open(const SpadParams& p,
                                                           const VolumeShape& shape,
                                                           const StreamOptions& options) {
  return openSpad(p, shape, options);
}
std::vector<std::string> SensorType<SpadParams>::warnings(const SpadParams& p,
                                                          const VolumeShape& shape, const Image*) {
  const TimeAxis& render = shape.axis;
  std::vector<std::string> out;
  if (p.irf.present()) {
    // The part of the response the window cannot hold is folded back into it
    // (convolveConserving), so the histogram's shape misleads.
    const TimeAxis axis = resolveBins(p.bins, render);
    const double irfWidth = static_cast<double>(p.irf.values.size()) * p.irf.sample_width_s;
    const double window = axis.bins * axis.bin_width_s;
    if (irfWidth > window) {
      const auto ps = [](double s) {
        char text[32];
        std::snprintf(text, sizeof text, "%.6g ps", s * 1e12);
        return std::string(text);
      };
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

}  // namespace tofsim::sensors
