#pragma once
// Single-photon avalanche diode with a time-to-digital converter, recording a
// per-pixel histogram of detections over N laser cycles, in synchronous
// (first-photon, pile-up) or free-running (dead time) mode. Counts are drawn
// exactly from the per-cycle probabilities (detection by detection by inverse
// CDF when there are few, else by binomial sampling, so the cost does not grow
// with N). Model and parameters: sensors/README.md, "SPAD".

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tofsim/sensors/Common.h"
#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/sensors/SensorStream.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::sensors {

enum class SpadMode { Synchronous, FreeRunning };

struct SpadParams {
  SensorCommon common;  ///< radiometry gives photons at the detector per laser pulse
  InstrumentBins bins;  ///< TDC bin width, offset and count
  SpadMode mode = SpadMode::Synchronous;
  int64_t cycles = 10000;              ///< laser pulses N, >= 1
  double pulse_fwhm_s = 0.0;           ///< Gaussian laser pulse FWHM, s, centred on t = 0
  double jitter_fwhm_s = 0.0;          ///< Gaussian timing jitter FWHM, s
  double jitter_tail_fraction = 0.0;   ///< fraction of detections with an extra exponential delay
  double jitter_tail_s = 0.0;          ///< time constant of that delay, s
  double pde = 0.3;                    ///< photon detection efficiency, [0, 1]
  double ambient_rate_per_s = 0.0;     ///< ambient photons arriving at the pixel, 1/s (PDE applies)
  double dark_count_rate_per_s = 0.0;  ///< dark counts, 1/s
  double dead_time_s = 0.0;            ///< free-running: non-paralysable, rounded to TDC bins
  /// Time gating: the detector is armed only in [gate_start, gate_start +
  /// gate_width) of each cycle (times as the TDC's), so light, ambient and
  /// dark counts outside cause no detection and no pile-up; a bin the gate
  /// edge crosses is armed for its covered fraction. 0 width: always armed.
  double gate_start_s = 0.0;
  double gate_width_s = 0.0;
  /// Free-running afterpulsing: each avalanche leaves a trapped carrier with
  /// this probability, released an Exp(afterpulse_delay) time after the end of
  /// the hold-off as a detection unless a photon comes first (the exact event
  /// engine, SpadEventEngine.h, draws these pixels). 0: none.
  double afterpulse_probability = 0.0;
  double afterpulse_delay_s = 10e-9;
  std::vector<std::array<int32_t, 2>> plot_pixels;  ///< (x, y) pixels to plot; empty = centre
  std::string colormap = "turbo";
};

/// Expected detections per cycle in each TDC bin of pixel (y, x) if nothing
/// were lost to pile-up or dead time: PDE * (signal * pulse * jitter + ambient)
/// + dark. `axis` is the TDC axis (resolveBins of params.bins).
void spadFluxPerCycle(const TransientVolume& volume, const SpadParams& params, const TimeAxis& axis,
                      int32_t y, int32_t x, std::vector<double>& flux);

/// Synchronous mode: probability per cycle that the first detection falls in
/// bin i, q_i * prod_{j<i} (1 - q_j) with q_i = 1 - exp(-flux_i).
std::vector<double> firstPhotonProbabilities(const std::vector<double>& flux);

/// Free-running mode: probability per cycle of a detection in bin i in the
/// periodic steady state of a detector that, after a detection in bin j, is
/// dead in bins j+1 .. j+deadBins (the laser period is the TDC range).
std::vector<double> freeRunningProbabilities(const std::vector<double>& flux, int32_t deadBins);

/// Coates' estimator: flux_i = -ln(1 - h_i / (N - sum_{j<i} h_j)). A bin that
/// took every remaining cycle gets ln(R + 1) (R remaining cycles); bins after
/// the remaining count reaches 0 get 0.
std::vector<double> coatesEstimate(const std::vector<double>& counts, int64_t cycles);

/// Outputs: "spad_counts" Array (H, W, bins); "spad_depth_peak" and
/// "spad_depth_coates" Images (H, W) in m (plus ColorMappedImages);
/// "spad_intensity" Image (H, W) total counts (plus ColorMappedImage);
/// "spad_histograms" HistogramPlot (pixels, bins).
std::vector<SensorOutput> runSpad(const TransientVolume& volume, const SpadParams& params,
                                  uint64_t seed);

/// The same model fed as the volume streams (SensorStream.h); spad_counts
/// goes to options.arrays when given. Throws InputError when the parameters
/// do not fit the shape (channel, plot pixels).
std::unique_ptr<SensorStream> openSpad(const SpadParams& params, const VolumeShape& shape,
                                       const StreamOptions& options);

}  // namespace tofsim::sensors
