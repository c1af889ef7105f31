#pragma once
// Streak camera: each selected image row becomes an x-t image (rows = time bins,
// time increasing downwards; columns = image x), blurred by a Gaussian temporal
// PSF and a Gaussian spatial blur along x, with photon shot noise, read noise,
// gain and saturation. Parameters: sensors/README.md, "Streak camera".

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tofsim/sensors/Common.h"
#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/sensors/SensorStream.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::sensors {

struct StreakParams {
  SensorCommon common;
  InstrumentBins bins;        ///< the streak's time axis
  std::vector<int32_t> rows;  ///< image rows to record; empty = all
  /// A moving scene (a capture sequence): a scanning streak camera records
  /// one row at a time, the i-th recorded row (in `rows` order) row_time
  /// after the one before, the first at the frame's time. 0: every row at once.
  double row_time_s = 0.0;
  double time_fwhm_s = 0.0;         ///< temporal PSF FWHM, s (0 = none)
  double spatial_fwhm_px = 0.0;     ///< spatial blur FWHM along x, pixels (0 = none)
  bool shot_noise = true;           ///< Poisson photo-electron noise
  double read_noise_e = 0.0;        ///< Gaussian read noise, photo-electrons RMS
  double gain_adu_per_e = 1.0;      ///< output units per photo-electron
  double saturation_adu = 65535.0;  ///< output clipped to [0, saturation_adu]
  std::string colormap = "inferno";
};

/// Outputs, per recorded row r: "streak_rowNNN" (NNN = r, 3 digits) as an Image
/// of shape (T, W) in ADU, and the same name as a ColorMappedImage.
std::vector<SensorOutput> runStreak(const TransientVolume& volume, const StreakParams& params,
                                    uint64_t seed);

/// The same model fed as the volume streams (SensorStream.h). It holds the
/// image of each recorded row (T x W values), and the render bins of one row
/// at a time. Throws InputError for a channel or row that does not fit.
std::unique_ptr<SensorStream> openStreak(const StreakParams& params, const VolumeShape& shape,
                                         const StreamOptions& options);

/// Name of the output for image row `row`: "streak_row042".
std::string streakRowName(int32_t row);

}  // namespace tofsim::sensors
