#pragma once
// Parameters every sensor model shares: which channel of the volume it sees,
// the radiometric scale from the volume's values to photo-electrons, and the
// instrument's own time bins. See sensors/README.md, "Common parameters".

#include <cstdint>
#include <optional>
#include <vector>

#include "tofsim/volume/TimeAxis.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::sensors {

/// One channel of the volume, or a weighted sum of all of them. By default the
/// plain sum of the channels: a sensor sees every colour the scene's light
/// carries (a blue object is not black to it), as a user would guess.
struct ChannelSelection {
  static constexpr int32_t kSumOfChannels = -1;
  int32_t index = kSumOfChannels;  ///< used when `weights` is empty: a channel, or the sum
  std::vector<double> weights;     ///< empty, or one weight per volume channel
};

/// Expected photo-electrons per unit of the volume's value (radiance integrated
/// over a bin, W s / (m^2 sr) for the render's light):
///   scale = source_scale * etendue_m2sr * optics_transmission * quantum_efficiency
///           * (wavelength_m > 0 ? wavelength_m / (h c) : 1)
/// With wavelength_m = 0 the volume is taken to count photons already (the
/// default: every factor 1, one photo-electron per unit).
struct Radiometry {
  double source_scale = 1.0;  ///< laser energy per pulse / exposure relative to the render's light
  double etendue_m2sr = 1.0;  ///< pixel area x aperture solid angle, m^2 sr
  double optics_transmission = 1.0;  ///< lens and filter transmission, [0, 1]
  double quantum_efficiency = 1.0;   ///< photo-electrons per photon, [0, 1]
  double wavelength_m = 0.0;         ///< 0: values already count photons

  double photoelectronsPerUnit() const;
};

struct SensorCommon {
  ChannelSelection channel;
  Radiometry radiometry;
};

/// The instrument's time bins: bin k covers [offset_s + k w, offset_s + (k+1) w).
/// Unset parts follow the render's axis, so by default the instrument window
/// is the render's: bin_width_s = 0 takes the render's width, no offset_s
/// takes the render's start, and count = 0 takes as many bins as cover the
/// render's axis end. An explicit offset or count wins (and may cut light off;
/// see windowLossFraction in WindowLoss.h).
struct InstrumentBins {
  double bin_width_s = 0.0;
  std::optional<double> offset_s;
  int32_t count = 0;
};

/// The concrete axis `bins` describes for a volume with axis `render`; it keeps
/// the render's index_of_refraction and camera_unwarp.
TimeAxis resolveBins(const InstrumentBins& bins, const TimeAxis& render);

/// Throws InputError when the selection does not fit the volume's channels.
void checkChannelSelection(const ChannelSelection& channel, const TransientVolume& volume);
/// The same for a volume of `channels` channels.
void checkChannelSelection(const ChannelSelection& channel, int32_t channels);

/// Expected photo-electrons per render bin of pixel (y, x): selected channel
/// times the radiometric scale. `out` gets volume.bins() values.
void pixelSignal(const TransientVolume& volume, const SensorCommon& common, int32_t y, int32_t x,
                 std::vector<double>& out);

/// The same for one pixel's `bins` x `channels` floats, wherever they are
/// (a streamed segment: SensorStream.h).
void pixelSignal(const float* pixel, int32_t bins, int32_t channels, const SensorCommon& common,
                 std::vector<double>& out);

/// Moves energy from the bins of `from` to those of `to`, each source bin's
/// energy spread uniformly over its interval and split by overlap. Energy inside
/// the target range is conserved exactly; energy outside it is dropped.
void resampleEnergy(const std::vector<double>& in, const TimeAxis& from, const TimeAxis& to,
                    std::vector<double>& out);

/// The same into the bins between consecutive `edges` (increasing, any
/// widths: a TDC's true bins), `out` getting edges.size() - 1 values.
void resampleEnergyToEdges(const std::vector<double>& in, const TimeAxis& from,
                           const std::vector<double>& edges, std::vector<double>& out);

}  // namespace tofsim::sensors
