#pragma once
// A linear-mode avalanche photodiode (APD) receiver, as most automotive
// lidars use (issue 43): the volume's light becomes a photocurrent (the
// common radiometry's photo-electrons: responsivity = quantum_efficiency x
// lambda q / (h c)), multiplied by a mean gain M with McIntyre's excess noise
// F(M) = k M + (1 - k)(2 - 1/M), the laser pulse's shape, the shot noise of
// signal, background and bulk dark current through the gain, the surface dark
// current's (not multiplied), a transimpedance amplifier's input noise, the
// receiver's electrical bandwidth (a Gaussian low-pass filter) and an optional
// ADC, sampled on the instrument bins; then a threshold detector (fixed, a
// constant false-alarm rate on the receiver's noise, or a cell-averaging
// CFAR whose threshold follows the local mean of the signal: a fog's
// backscatter, a sloped background) finds up to `max_returns` echoes per
// pixel (a lidar's beam). Parameters and outputs: sensors/README.md, "Linear-mode APD".

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tofsim/sensors/Common.h"
#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/sensors/SensorStream.h"
#include "tofsim/sensors/TimeKernel.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::sensors {

/// Fixed: threshold_A. Cfar: the background's mean + z sigma (its noise
/// alone, known to the receiver). CaCfar: cell-averaging CFAR, per sample
/// the mean of its training cells + z kappa sigma(that mean) (apdThresholds).
enum class ApdThreshold { Fixed, Cfar, CaCfar };

/// A 905 nm silicon APD's radiometry: the volume's light as energy (the
/// wavelength converts it to photons), a quantum efficiency of 0.8
/// (responsivity 0.584 A/W at unity gain).
inline SensorCommon apdDefaultCommon() {
  SensorCommon c;
  c.radiometry.wavelength_m = 905e-9;
  c.radiometry.quantum_efficiency = 0.8;
  return c;
}

struct ApdParams {
  SensorCommon common = apdDefaultCommon();
  InstrumentBins bins;  ///< the digitiser's samples
  double gain = 100.0;              ///< mean avalanche gain M, >= 1
  double ionization_ratio = 0.02;   ///< k: hole / electron ionisation ratio, [0, 1]
  double background_rate = 0.0;     ///< ambient primary photo-electrons per second
  double dark_current_bulk_A = 1e-11;    ///< primary bulk dark current (multiplied), A
  double dark_current_surface_A = 1e-9;  ///< surface dark current (not multiplied), A
  double tia_noise_A_per_rtHz = 2e-12;   ///< TIA input-referred current noise density
  double bandwidth_Hz = 150e6;      ///< receiver -3 dB bandwidth (Gaussian filter); 0: none
  double pulse_fwhm_s = 4e-9;       ///< the laser pulse (Gaussian, on the signal only)
  int32_t adc_bits = 0;             ///< 0: no amplitude quantisation
  double adc_full_scale_A = 1e-4;   ///< ADC range [0, full scale) in input current
  ApdThreshold threshold_mode = ApdThreshold::Cfar;
  double threshold_A = 1e-6;        ///< fixed threshold, A
  double false_alarm = 1e-5;        ///< CFAR, CA-CFAR: false alarms per sample
  int32_t cfar_guard_cells = 4;     ///< CA-CFAR: samples left out each side of the one tested
  int32_t cfar_training_cells = 16; ///< CA-CFAR: samples averaged each side, beyond the guard
  int32_t max_returns = 3;          ///< echoes kept per pixel (time order)
  bool output_waveforms = true;     ///< apd_waveforms (H, W, T)
  std::string colormap = "turbo";
};

/// McIntyre's excess noise factor F(M) = k M + (1 - k)(2 - 1/M).
double apdExcessNoise(double gain, double k);

/// Unity-gain responsivity q x quantum_efficiency x lambda / (h c), A/W
/// (0 when the wavelength is 0: the volume then counts photons).
double apdResponsivity_A_per_W(const Radiometry& r);

/// The impulse response's sigma of a Gaussian low-pass filter whose -3 dB
/// bandwidth is `bandwidth_Hz` (0: none), s.
double apdFilterSigma_s(double bandwidth_Hz);

/// The receiver as resolved on a digitiser axis: the filters and the noise
/// that needs no signal, shared by the model and its tests.
struct ApdReceiver {
  TimeAxis axis;          ///< the samples
  BinKernel pulse;        ///< the laser pulse on the samples
  BinKernel filter;       ///< the electrical bandwidth's impulse response
  double excessNoise = 1.0;
  /// Noise bandwidth of the sampled filter, sum(h^2) / (2 dt), Hz.
  double noiseBandwidth_Hz = 0.0;
  /// Per sample without signal: mean current and its standard deviation, A.
  double backgroundMean_A = 0.0, backgroundSigma_A = 0.0;
  double threshold_A = 0.0;  ///< the detector's threshold (CA-CFAR: on the background)
  /// The noise model at any mean current m (apdNoiseSigma_A): sigma(m)^2 =
  /// floorVariance_A2 + electronVariance_A2 x electrons(m), electrons(m) =
  /// (m - surfaceMean_A) / electronCurrent_A the multiplied primaries a
  /// sample's mean holds.
  double electronCurrent_A = 0.0, electronVariance_A2 = 0.0, floorVariance_A2 = 0.0,
         surfaceMean_A = 0.0;
  /// CA-CFAR: z with P(N(0, 1) > z) = false_alarm, and per sample kappa,
  /// the standard deviation of (sample - its training cells' mean) over a
  /// sample's sigma, from the filter's correlation (sqrt(1 + 1 / (2 N)) for
  /// white samples and N cells a side; one-sided near the axis' ends).
  double cfarZ = 0.0;
  std::vector<double> cfarKappa;
};
ApdReceiver apdReceiver(const ApdParams& p, const TimeAxis& render);

/// The receiver's noise sigma (A, per filtered sample) at mean current m:
/// the shot noise of the primaries m holds through the gain, the surface
/// dark current's and the TIA's.
double apdNoiseSigma_A(const ApdReceiver& rx, double meanCurrent_A);

/// Each sample's threshold (rx.axis.bins): rx.threshold_A, or with
/// `threshold_mode: ca_cfar` the mean m_t of the training cells t - G - N ..
/// t - G - 1 and t + G + 1 .. t + G + N (those on the axis) plus rx.cfarZ x
/// rx.cfarKappa[t] x apdNoiseSigma_A(m_t). For Gaussian noise on a linear
/// background the false-alarm rate is then false_alarm exactly: the two
/// windows' mean is the background's at t, and (sample - m_t) is normal of
/// variance kappa^2 sigma^2 (sensors/README.md, "CA-CFAR").
void apdThresholds(const ApdParams& p, const ApdReceiver& rx, const std::vector<double>& samples_A,
                   std::vector<double>& out_A);

/// z with P(N(0, 1) > z) = p, for 0 < p < 1.
double normalUpperQuantile(double p);

/// Outputs: apd_waveforms (H, W, T) A (with output_waveforms), apd_range and
/// apd_amplitude (H, W, max_returns) m and A (NaN: no echo), apd_returns (H,
/// W) echo count, apd_first_range (Image and picture).
std::unique_ptr<SensorStream> openApd(const ApdParams& params, const VolumeShape& shape,
                                      const StreamOptions& options);
std::vector<SensorOutput> runApd(const TransientVolume& volume, const ApdParams& params,
                                 uint64_t seed, int threads = 0);

}  // namespace tofsim::sensors
