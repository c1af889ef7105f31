// The sensor descriptors of SensorType.h, one block per model.
#include "tofsim/sensors/SensorType.h"
#include "tofsim/sensors/WindowLoss.h"

namespace tofsim::sensors {

namespace {
// A handful of images and PNG pictures beside each sensor's arrays (float32
// image + 8-bit RGB picture per pixel), as a bound for the output estimate.
std::uintmax_t imageBytes(int32_t width, int32_t height) {
  return 8 * static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height) * (4 + 3);
}
}  // namespace

// --- streak --------------------------------------------------------------------
std::vector<SensorOutput> SensorType<StreakParams>::run(const StreakParams& p,
                                                        const SensorInputs& in) {
  return runStreak(*in.volume, p, in.seed);
}
std::vector<std::string> SensorType<StreakParams>::warnings(const StreakParams&,
                                                            const SensorInputs&) {
  return {};
}
std::uintmax_t SensorType<StreakParams>::outputBytes(const StreakParams& p, int32_t width,
                                                     int32_t height, const TimeAxis& render) {
  const std::uintmax_t bins = resolveBins(p.bins, render).bins;
  const std::uintmax_t rows = p.rows.empty() ? static_cast<std::uintmax_t>(height) : p.rows.size();
  return rows * static_cast<std::uintmax_t>(width) * bins * (4 + 3) + imageBytes(width, height);
}
double SensorType<StreakParams>::windowLossFraction(const StreakParams& p,
                                                    const TransientVolume& volume) {
  return instrumentWindowLoss(p.common, p.bins, p.rows, volume);
}

// --- spad ----------------------------------------------------------------------
std::vector<SensorOutput> SensorType<SpadParams>::run(const SpadParams& p, const SensorInputs& in) {
  return runSpad(*in.volume, p, in.seed);
}
std::vector<std::string> SensorType<SpadParams>::warnings(const SpadParams&, const SensorInputs&) {
  return {};
}
std::uintmax_t SensorType<SpadParams>::outputBytes(const SpadParams& p, int32_t width,
                                                   int32_t height, const TimeAxis& render) {
  const std::uintmax_t bins = resolveBins(p.bins, render).bins;
  const auto pixels = static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height);
  return pixels * bins * 4 + imageBytes(width, height);
}
double SensorType<SpadParams>::windowLossFraction(const SpadParams& p,
                                                  const TransientVolume& volume) {
  return instrumentWindowLoss(p.common, p.bins, {}, volume);
}

// --- cwtof ---------------------------------------------------------------------
std::vector<SensorOutput> SensorType<CwTofParams>::run(const CwTofParams& p,
                                                       const SensorInputs& in) {
  return runCwTof(*in.volume, p, in.seed, CwTofReferences{in.groundTruthDepth_m, in.directOnly});
}
std::vector<std::string> SensorType<CwTofParams>::warnings(const CwTofParams& p,
                                                           const SensorInputs& in) {
  return cwtofWarnings(p, in.volume->axis(), in.groundTruthDepth_m);
}
std::uintmax_t SensorType<CwTofParams>::outputBytes(const CwTofParams& p, int32_t width,
                                                    int32_t height, const TimeAxis&) {
  const auto pixels = static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height);
  // The raw images and the phase array, then four images with their
  // pictures per frequency (phase, amplitude, depth, multipath error).
  const std::uintmax_t F = p.frequencies_Hz.size();
  const auto steps = static_cast<std::uintmax_t>(p.phase_steps);
  return F * (steps + 1) * pixels * 4 + F * 4 * pixels * (4 + 3) + imageBytes(width, height);
}
double SensorType<CwTofParams>::windowLossFraction(const CwTofParams&, const TransientVolume&) {
  return 0.0;
}

}  // namespace tofsim::sensors
