#pragma once
// Continuous-wave (amplitude-modulated) time of flight: N phase-stepped
// correlation images per modulation frequency, each bin of the impulse response
// correlated exactly (averaged over the bin, not sampled at its centre), then
// phase, amplitude, offset, multi-frequency unwrapping and depth. Model and
// parameters: sensors/README.md, "Continuous-wave ToF".

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/sensors/Common.h"
#include "tofsim/sensors/CwTofDevice.h"
#include "tofsim/sensors/CwTofWaveform.h"
#include "tofsim/sensors/SensorOutput.h"
#include "tofsim/sensors/SensorStream.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::sensors {

/// Sine, square (50 % duty: a triangle correlation), or Measured: the
/// CorrelationWaveform(s) of CwTofParams::correlation.
enum class Waveform { Sine, Square, Measured };

struct CwTofParams {
  /// The device preset whose values were the defaults (CwTofPresets.h); empty: none.
  std::string preset;
  SensorCommon common;  ///< radiometry gives photo-electrons per raw image (one phase step)
  std::vector<double> frequencies_Hz{20e6};  ///< modulation frequencies, each > 0
  int32_t phase_steps = 4;                   ///< N >= 3, reference phases 2 pi k / N
  Waveform waveform = Waveform::Sine;
  /// Waveform::Measured: one waveform for every frequency, or one per
  /// frequency (in the order of frequencies_Hz). Empty otherwise.
  std::vector<CorrelationWaveform> correlation;
  /// m in (0, 1]: C_k = 0.5 (E + ambient) + 0.5 m sum_t E_t rho_t (the AC part).
  double modulation_contrast = 1.0;
  double ambient_e = 0.0;     ///< ambient photo-electrons per raw image and pixel
  bool shot_noise = true;     ///< Poisson noise on each raw image
  double read_noise_e = 0.0;  ///< Gaussian read noise per raw image, photo-electrons RMS
  double max_depth_m = 0.0;   ///< unwrapping range; 0 = (c / eta) / (2 gcd(frequencies)), capped
  std::string colormap = "turbo";
  /// Also the multipath error of each bounce order k = 0..N: the noise-free
  /// depth of direct + bounces 1..k against the ground truth. Needs the
  /// render's direct and bounce components (StreamOptions::bounces).
  bool multipath_by_order = false;

  // The device stage (CwTofDevice.h, sensors/README.md "Raw frames as a
  // device delivers them"); every default leaves it off.
  /// Seed of the fixed pattern (delay, gains, offsets), not the noise seed.
  int64_t fpn_seed = 0;
  double delay_sigma_s = 0.0;   ///< per-pixel time offset delta_p, Gaussian sigma, s
  CwTofPixelMap delay_map;      ///< measured delta_p, s, in place of delay_sigma_s
  double gain_sigma = 0.0;      ///< per-pixel, per-tap relative gain sigma
  CwTofPixelMap gain_map;       ///< measured relative gain (both taps), in place of gain_sigma
  double offset_sigma_e = 0.0;  ///< per-pixel raw offset, Gaussian sigma, e-
  CwTofPixelMap offset_map;     ///< measured raw offset, e-, in place of offset_sigma_e
  /// 1: each raw is one tap's charge; 2: tap A at theta, tap B at theta + pi,
  /// the raw is A - B.
  int32_t taps = 1;
  double tap_a_gain = 1.0, tap_b_gain = 1.0;  ///< global gain of each tap
  bool output_taps = false;                   ///< also `cwtof_raw_taps` (F, N, 2, H, W), e-
  /// beta in [0, 1]: beta min(A, B) of common-mode charge removed from both
  /// taps after integration (taps: 2); the shot noise of all of it is kept.
  double ambient_suppression = 0.0;
  double dark_current_e = 0.0;  ///< dark electrons per tap and raw (Poisson with the light)
  double full_well_e = 0.0;     ///< per tap, e-, applied before the difference; 0: none
  int32_t adc_bits = 0;         ///< 0: no ADC (no DN outputs); else 1..24
  double adc_gain_dn_per_e = 1.0;
  double adc_offset_dn = 0.0;
  CwTofCompanding companding;  ///< none: linear
  /// Capture order, a permutation of every (f, n); empty: frequency-major,
  /// step-minor. Metadata only (the scene is static during a capture).
  std::vector<CwTofCaptureStep> capture_order;
  double integration_time_s = 0.0;  ///< per raw, s (time stamps)
  double readout_gap_s = 0.0;       ///< between raws, s (time stamps)
  /// PoissonRead (shot_noise, read_noise) or Table (noise_table, in place of both).
  CwTofNoiseModel noise_model = CwTofNoiseModel::PoissonRead;
  CwTofNoiseTable noise_table;
};

/// Mean over [t0_s, t1_s) of the normalised correlation rho(2 pi f t - phase):
/// cos for Sine; for Square (50% duty illumination against a 50% duty
/// reference) the triangle wave with rho(0) = 1, rho(pi) = -1. Built-in
/// waveforms only (Measured: PhaseCorrelation::mean).
double binCorrelation(Waveform waveform, double frequency_Hz, double phase_rad, double t0_s,
                      double t1_s);

/// Sweep points per frequency of the `cwtof_wiggling_error` output.
inline constexpr int32_t kWigglingSweepPoints = 1024;

/// The wiggling error (F, S) in m, S = kWigglingSweepPoints: for frequency f
/// and sweep point j, a single noise-free return (a delta: a bin of zero
/// width, through the same per-bin correlation as the raw images) at delay
/// theta_j / (2 pi f), theta_j = 2 pi (j + 0.5) / S, its N-step wrapped depth
/// minus k theta_j / (2 pi f), folded into [-R/2, R/2] of R = k / f; k as for
/// unwrapDepth_m. Throws InputError for parameters that do not fit.
std::vector<double> wigglingError_m(const CwTofParams& params, double depthPerSecond_m_per_s);

/// The noise-free phases (F, rad, [0, 2 pi)) runCwTof estimates, in double,
/// for a pixel whose expected photo-electrons per bin of `axis` are `signal`
/// (no ambient, no noise): the same correlation table and estimator.
/// delay_s: the pixel's fixed-pattern time offset delta_p (0: none).
std::vector<double> noiseFreePhases(const CwTofParams& params, const TimeAxis& axis,
                                    const std::vector<double>& signal, double delay_s = 0.0);

/// Phase in [0, 2 pi) and amplitude from N raw values C_k taken at reference
/// phases 2 pi k / N: atan2(sum C_k sin, sum C_k cos), (2 / N) |sum C_k e^{i phi_k}|.
void phaseFromSteps(const double* raw, int32_t steps, double& phase_rad, double& amplitude);

/// Depth from wrapped phases at several frequencies: picks the wrap counts that
/// agree best within [0, maxDepth_m), then averages the per-frequency depths
/// weighted by f^2. depth = k * phase / (2 pi f) with k the metres of depth per
/// second of delay, TimeAxis::depthPerSecond_m_per_s: (c / eta) / 2 for a
/// co-located light and camera.
double unwrapDepth_m(const std::vector<double>& phases_rad,
                     const std::vector<double>& frequencies_Hz, double maxDepth_m,
                     double depthPerSecond_m_per_s);

/// The range unwrapDepth_m searches for these parameters, m (max_depth, or
/// k / gcd(frequencies) capped, k as for unwrapDepth_m).
double unwrapRange_m(const CwTofParams& params, double depthPerSecond_m_per_s);

/// The range the `cwtof_depth` output spans, m: one frequency's unambiguous
/// range k / f when there is one (nothing is unwrapped), else unwrapRange_m.
double depthRange_m(const CwTofParams& params, double depthPerSecond_m_per_s);

/// The stem suffix that names a frequency's outputs: "20MHz", "12.5MHz" (%g of MHz).
std::string frequencyLabel(double frequency_Hz);

/// Optional inputs for the multipath error outputs.
struct CwTofReferences {
  const Image* groundTruthDepth_m = nullptr;    ///< (H, W, 1), metres; <= 0 or NaN = unknown
  const TransientVolume* directOnly = nullptr;  ///< the direct component of the same render
  /// Bounces 1..N of the same render (with directOnly), for multipath_by_order.
  const std::vector<const TransientVolume*>* bounces = nullptr;
};

/// Warnings for the person running the sensor: one when the ground-truth
/// depth reaches beyond depthRange_m (the measured depths wrap there). Empty
/// without a ground truth.
std::vector<std::string> cwtofWarnings(const CwTofParams& params, const TimeAxis& axis,
                                       const Image* groundTruthDepth_m);

/// Outputs (sensors/README.md, "Continuous-wave ToF"): "cwtof_raw" Array
/// (F, N, H, W) photo-electrons; "cwtof_phase" Array (F, H, W) rad;
/// "cwtof_depth" (unwrapped when F >= 2, else the one frequency's wrapped
/// depth) and "cwtof_amplitude" (first frequency) Images (H, W); per frequency
/// f, "cwtof_phase_<f>", "cwtof_amplitude_<f>" and "cwtof_depth_<f>" (wrapped)
/// Images; with a ground truth, "cwtof_mpi_error" (noise-free depth - ground
/// truth) and per frequency "cwtof_multipath_error_<f>", and
/// "cwtof_wiggling_error_map" (the depth error of a noise-free single return
/// at each pixel's true depth: the waveform's, multipath excluded); with a direct-only
/// volume, "cwtof_mpi_error_direct" (noise-free depth - direct-only depth);
/// with the lens's PSF (StreamOptions::psfOnRaws or beforePsf),
/// "cwtof_psf_error" (noise-free depth with it - without it); in a frame of
/// a capture sequence whose raws are taken at different times,
/// "cwtof_motion_error" (noise-free depth of the raws as taken - that of the
/// light at the frame's time, through the same device);
/// with multipath_by_order, "cwtof_multipath_error_by_order" Array (N + 1,
/// H, W): order k = the depth of direct + bounces 1..k - ground truth, NaN
/// where that light is zero, and a ColorMappedImage of each order,
/// "cwtof_multipath_error_order<k>"; always "cwtof_wiggling_error" Array
/// (F, S) m (wigglingError_m) with its max |error| and RMS as attributes.
/// Every error is wrapped into (-R/2, R/2] of its depth's range R, so a phase
/// wrap never reads as multipath. Every Image comes with a ColorMappedImage.
/// The device stage (CwTofDevice.h) adds, where its keys ask for them,
/// "cwtof_raw_dn" Array (F, N, H, W) DN, with a capture_order the same raws
/// in capture order "cwtof_raw_sequence" Array (F N, H, W) DN, "cwtof_device_phase" Array (F, H,
/// W), "cwtof_device_depth" (NaN where saturated) and "cwtof_device_amplitude" Images,
/// "cwtof_saturated", "cwtof_raw_taps" Array (F, N, 2, H, W) e- and the fixed-pattern maps;
/// "cwtof_raw" is then the device's raw in e-.
std::vector<SensorOutput> runCwTof(const TransientVolume& volume, const CwTofParams& params,
                                   uint64_t seed, const CwTofReferences& references = {});

/// The same model fed as the volume streams (SensorStream.h); spans carry
/// the direct component when options.directOnly (and the bounces when
/// options.bounces), and finish() takes the ground-truth depth. Throws
/// InputError when the parameters do not fit, or multipath_by_order is on
/// and options.bounces is not set.
std::unique_ptr<SensorStream> openCwTof(const CwTofParams& params, const VolumeShape& shape,
                                        const StreamOptions& options);

}  // namespace tofsim::sensors
