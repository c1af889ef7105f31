#include "tofsim/sensors/Streak.h"

#include <algorithm>
#include <cstdio>

#include "tofsim/sensors/Random.h"
#include "tofsim/sensors/TimeKernel.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
constexpr uint32_t kStreakStreamTag = 0x5354;  // "ST"
}

std::string streakRowName(int32_t row) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "streak_row%03d", static_cast<int>(row));
  return buf;
}

std::vector<SensorOutput> runStreak(const TransientVolume& volume, const StreakParams& p,
                                    uint64_t seed) {
  TOFSIM_CHECK(p.time_fwhm_s >= 0.0 && p.spatial_fwhm_px >= 0.0 && p.read_noise_e >= 0.0);
  TOFSIM_CHECK(p.gain_adu_per_e > 0.0 && p.saturation_adu > 0.0);
  checkChannelSelection(p.common.channel, volume);
  std::vector<int32_t> rows = p.rows;
  if (rows.empty()) {
    for (int32_t y = 0; y < volume.height(); ++y) rows.push_back(y);
  }
  for (int32_t y : rows) {
    if (y < 0 || y >= volume.height()) {
      throw InputError("streak row " + std::to_string(y) + " is outside the image (height " +
                       std::to_string(volume.height()) + ")");
    }
  }
  const TimeAxis axis = resolveBins(p.bins, volume.axis());
  const int32_t T = axis.bins;
  const int32_t W = volume.width();
  const BinKernel timeKernel = gaussianKernel(fwhmToSigma(p.time_fwhm_s), axis.bin_width_s);
  const BinKernel spaceKernel = gaussianKernel(fwhmToSigma(p.spatial_fwhm_px), 1.0);

  std::vector<SensorOutput> outputs;
  std::vector<double> signal, resampled;
  std::vector<double> a(static_cast<std::size_t>(T) * W), b(a.size());  // (T, W)
  for (int32_t y : rows) {
    for (int32_t x = 0; x < W; ++x) {
      pixelSignal(volume, p.common, y, x, signal);
      resampleEnergy(signal, volume.axis(), axis, resampled);
      for (int32_t t = 0; t < T; ++t) a[static_cast<std::size_t>(t) * W + x] = resampled[t];
    }
    for (int32_t x = 0; x < W; ++x) convolveConserving(&a[x], T, W, timeKernel, &b[x]);
    for (int32_t t = 0; t < T; ++t) {
      const std::size_t row = static_cast<std::size_t>(t) * W;
      convolveConserving(&b[row], W, 1, spaceKernel, &a[row]);
    }

    SensorOutput image;
    image.name = streakRowName(y);
    image.kind = SensorOutput::Kind::Image;
    image.shape = {T, W};
    image.axes = {"t", "x"};
    image.time = axis;
    image.attributes = {{"row", y}};
    image.unit = "ADU";
    image.description = "streak image of row " + std::to_string(y) + " (rows: time from " +
                        std::to_string(axis.start_s * 1e9) + " ns, step " +
                        std::to_string(axis.bin_width_s * 1e12) + " ps; columns: x)";
    image.data.resize(a.size());
    for (int32_t x = 0; x < W; ++x) {
      Rng rng(seed, pixelStream(kStreakStreamTag, static_cast<uint64_t>(y) * W + x));
      for (int32_t t = 0; t < T; ++t) {
        const std::size_t i = static_cast<std::size_t>(t) * W + x;
        double e = p.shot_noise ? static_cast<double>(rng.poisson(std::max(0.0, a[i]))) : a[i];
        if (p.read_noise_e > 0.0) e += rng.normal(0.0, p.read_noise_e);
        image.data[i] = static_cast<float>(std::clamp(e * p.gain_adu_per_e, 0.0, p.saturation_adu));
      }
    }
    SensorOutput png = image;
    png.kind = SensorOutput::Kind::ColorMappedImage;
    png.colormap = p.colormap;
    outputs.push_back(std::move(image));
    outputs.push_back(std::move(png));
  }
  return outputs;
}

}  // namespace tofsim::sensors
