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
enum class SpadAfterpulseCount { Bernoulli, Poisson };
enum class SpadAfterpulseTraps { Reset, Keep };
enum class SpadEngine { Auto, Exact, Fast };

/// The neighbours an avalanche can trigger by crosstalk: the 4 sharing an
/// edge, or the 8 sharing an edge or a corner (each with the same probability).
enum class CrosstalkNeighbours { Four = 4, Eight = 8 };

/// A measured instrument response (the config's `irf:`), in place of the
/// Gaussian pulse and jitter: the delay from a photon's arrival to its
/// timestamp is distributed as `values`, constant over each sample (the
/// sample at time t_k covers [t_k - w/2, t_k + w/2), w = sample_width_s), and
/// transferred into the TDC bins exactly (piecewise-constant density,
/// TimeKernel.h). The sensors library reads no file: the config layer fills
/// `values` from the file it names.
struct SpadIrf {
  enum class TimeZero { Peak, Centroid, Time };
  std::string file;              ///< the file it came from (metadata); empty: no IRF
  double bin_width_s = 0.0;      ///< as configured (.npy); 0: from the CSV's time column
  TimeZero t0 = TimeZero::Peak;  ///< which time of the IRF's axis is zero delay
  double t0_s = 0.0;             ///< TimeZero::Time: that time, s
  double floor = 0.0;            ///< subtracted from every value; values below it become 0
  std::vector<double> values;    ///< after the floor: >= 0, sum > 0, any scale; empty: no IRF
  double first_time_s = 0.0;     ///< t_0, the time of values[0] on the IRF's own axis
  double sample_width_s = 0.0;   ///< w, the sample spacing, s

  bool present() const { return !values.empty(); }
};

/// A TDC's differential non-linearity (the config's `tdc_dnl`, a list or a
/// file the config layer reads): code i is LSB (1 + values[i]) wide, LSB the
/// nominal bin width, so the true edges are e_k = offset + sum_{i<k} LSB (1 +
/// DNL_i) and pile-up acts on the true, unequal bins.
struct SpadDnl {
  std::string file;            ///< the file it came from; empty: a list in the config
  std::vector<double> values;  ///< one per TDC bin, each > -1, sum 0; empty (or all 0): none

  bool present() const { return !values.empty(); }
};

/// A measured dark count rate per pixel (the config's `dark_count_map`, a
/// .npy the config layer reads), in place of the log-normal draw.
struct SpadDarkCountMap {
  std::string file;                 ///< the file it came from (metadata)
  int32_t height = 0, width = 0;    ///< its shape, the image's
  std::vector<double> rates_per_s;  ///< row-major (y, x), counts / s, >= 0; empty: none

  bool present() const { return !rates_per_s.empty(); }
};

/// A measured afterpulse delay density (the config's `afterpulse_delay_table`,
/// a file the config layer reads), in place of the exponentials of
/// afterpulse_delays_s: row k, delay t_k (from the end of the hold-off) and
/// value v_k (a density, any scale), is the bin [e_k, e_(k+1)) of a
/// piecewise-constant density, e_k the midpoints between consecutive delays,
/// e_0 = max(0, t_0 - (t_1 - t_0) / 2) and e_n = t_(n-1) + (t_(n-1) - t_(n-2))
/// / 2 (an evenly spaced table: each row its bin's centre).
struct SpadAfterpulseTable {
  std::string file;                   ///< the file it came from (metadata)
  std::vector<double> delays_s;       ///< t_k, increasing, >= 0
  std::vector<double> edges_s;        ///< e_0 .. e_n
  std::vector<double> density_per_s;  ///< v_k normalised: sum v_k (e_(k+1) - e_k) = 1; empty: none

  bool present() const { return !density_per_s.empty(); }
};

/// The table of rows (delays_s[k], values[k]) as SpadAfterpulseTable says:
/// its edges and its density normalised. Needs >= 2 increasing delays >= 0,
/// values >= 0 with a positive area (the config layer checks them first).
SpadAfterpulseTable afterpulseTable(std::string file, std::vector<double> delays_s,
                                    const std::vector<double>& values);

/// The time of the IRF's axis that is zero delay: the first maximum's t_k
/// (Peak), the mean sum v_k t_k / sum v_k (Centroid, the density's exact
/// mean), or t0_s (Time).
double irfTimeZero_s(const SpadIrf& irf);

/// The deepest counter a SPAD's counter_bits may ask for: the config's range
/// (SensorFields.h) and the model's check (SpadParamsCheck.cpp) both read it.
inline constexpr int32_t kMaxCounterBits = 32;

struct SpadParams {
  /// The device preset whose values were the defaults (SpadPresets.h); empty: none.
  std::string preset;
  SensorCommon common;  ///< radiometry gives photons at the detector per laser pulse
  InstrumentBins bins;  ///< TDC bin width, offset and count
  SpadMode mode = SpadMode::Synchronous;
  int64_t cycles = 10000;  ///< laser pulses N, >= 1
  /// A moving scene (a capture sequence): the cycles are spread evenly over
  /// [0, exposure_time) after the frame's time, and their flux is the mean of
  /// the light at the middles of sequence.exposure_samples equal parts of it
  /// (SensorStream::sampleTimes_s). 0: every cycle at the frame's time.
  double exposure_time_s = 0.0;
  double pulse_fwhm_s = 0.0;           ///< Gaussian laser pulse FWHM, s, centred on t = 0
  double jitter_fwhm_s = 0.0;          ///< Gaussian timing jitter FWHM, s
  double jitter_tail_fraction = 0.0;   ///< fraction of detections with an extra exponential delay
  double jitter_tail_s = 0.0;          ///< time constant of that delay, s
  double pde = 0.3;                    ///< photon detection efficiency, [0, 1]
  double ambient_rate_per_s = 0.0;     ///< ambient photons arriving at the pixel, 1/s (PDE applies)
  double dark_count_rate_per_s = 0.0;  ///< dark counts, 1/s
  /// Dead time after every avalanche (recorded or not), non-paralysable,
  /// rounded to TDC bins; it may run into later cycles (synchronous: the
  /// cycles it spans are lost after a detection).
  double dead_time_s = 0.0;
  /// Synchronous: detections the TDC records per cycle (a multi-stop TDC),
  /// each followed by the dead time; 0: every one. 1: first photon.
  int64_t tdc_stops = 1;
  /// Time gating: the detector is armed only in [gate_start, gate_start +
  /// gate_width) of each cycle (times as the TDC's), so light, ambient and
  /// dark counts outside cause no detection and no pile-up; a bin the gate
  /// edge crosses is armed for its covered fraction. 0 width: always armed.
  double gate_start_s = 0.0;
  double gate_width_s = 0.0;
  /// Finite gate transitions: the sensitivity g(t) rises linearly from 0 to 1
  /// over gate_rise, centred on gate_start, and falls back over gate_fall,
  /// centred on gate_start + gate_width (gate_width stays the 50 % width);
  /// each bin sees the exact average of g over it. 0: hard edges.
  double gate_rise_s = 0.0;
  double gate_fall_s = 0.0;
  /// Per-pixel gate skew: pixel (y, x)'s whole gate moved by a N(0, sigma)
  /// time of the fixed pattern (fpn_seed, not the noise seed). 0: none.
  double gate_skew_sigma_s = 0.0;
  /// Gated 1-bit frames (SPAD512S-class arrays, SpadGatedFrames.h): each of
  /// gated_frames frames integrates pulses_per_frame pulses into a 1-bit
  /// latch set by a detection inside the gate; the frames are summed per gate
  /// position k, the gate moved by k gate_step (gate_positions of them).
  /// 0 frames: off. The histogram path keeps position 0's gate.
  int64_t gated_frames = 0;
  int64_t pulses_per_frame = 1;
  double gate_step_s = 0.0;
  int32_t gate_positions = 1;
  /// Counter depth: every count (spad_counts' bins, the gated counts) clips
  /// at 2^counter_bits - 1. 0: unlimited. At most kMaxCounterBits.
  int32_t counter_bits = 0;
  SpadDnl tdc_dnl;  ///< TDC differential non-linearity; none: equal bins
  /// Afterpulsing (both modes; the exact event engine, SpadEventEngine.h,
  /// draws these pixels): each avalanche fills a Bernoulli(p) or Poisson(mu)
  /// number of traps (afterpulse_count, p or mu = afterpulse_probability),
  /// each released a delay after the end of its dead time, from a mixture of
  /// exponentials of means afterpulse_delays_s and weights afterpulse_weights
  /// (empty: equal); a release while the detector is live is an avalanche
  /// (recorded if the TDC has a stop left), one while it is dead is lost.
  /// Reset: each avalanche empties the traps of the ones before. 0: none.
  double afterpulse_probability = 0.0;
  SpadAfterpulseCount afterpulse_count = SpadAfterpulseCount::Bernoulli;
  std::vector<double> afterpulse_delays_s = {10e-9};
  std::vector<double> afterpulse_weights;
  /// A measured delay density in place of the exponentials (exclusive with
  /// afterpulse_delays_s and afterpulse_weights, which it leaves unused).
  SpadAfterpulseTable afterpulse_delay_table;
  SpadAfterpulseTraps afterpulse_traps = SpadAfterpulseTraps::Reset;
  /// Which draws: Auto, the exact event engine where an effect needs it
  /// (multi-stop, dead time past the cycle, afterpulses), the fast draws
  /// elsewhere (and exact crosstalk where the gate needs it); Exact, the
  /// engine for every pixel and crosstalk exact (the reference); Fast,
  /// afterpulses to first order as extra flux on the fast draws
  /// (SpadAfterpulseFlux.h), the engine only for the other effects.
  SpadEngine engine = SpadEngine::Auto;
  /// Crosstalk: each avalanche triggers one in each of its neighbours with
  /// this probability, after a delay (0: prompt, in the same bin; else
  /// exponential with this mean); 0: none. Drawn on the fast path to first
  /// order, from the neighbours' expected avalanches (SpadCrosstalk.h);
  /// exact by the array driver (SpadArrayEvents.h) with engine Exact, and
  /// with Auto where the gate has ramps or skew or a delayed arrival meets it.
  double crosstalk_probability = 0.0;
  CrosstalkNeighbours crosstalk_neighbours = CrosstalkNeighbours::Four;
  double crosstalk_delay_s = 0.0;
  SpadIrf irf;  ///< measured response; when present, pulse and jitter (all 0) are not used
  /// Array non-uniformity, a fixed pattern drawn from fpn_seed alone (not the
  /// noise seed: the same device under every noise seed), per pixel (y, x):
  /// dead with probability dead_pixel_fraction (PDE and DCR 0), else hot with
  /// probability hot_pixel_fraction (DCR = hot_pixel_rate_per_s), else DCR
  /// log-normal with median dark_count_rate_per_s and ln-sigma
  /// dark_count_log_sigma; PDE = pde (1 + pde_spread z) clipped to [0, 1]
  /// (SpadPixelMaps.h).
  int64_t fpn_seed = 0;
  double pde_spread = 0.0;
  double dark_count_log_sigma = 0.0;
  SpadDarkCountMap dark_count_map;  ///< measured DCR per pixel, in place of the log-normal
  double hot_pixel_fraction = 0.0;
  double hot_pixel_rate_per_s = 0.0;
  double dead_pixel_fraction = 0.0;
  /// A return (first / strongest / last, SpadEstimators.h): the matched-filter
  /// response this many background noise sigmas above the background.
  double return_threshold_sigma = 5.0;
  /// FLIM outputs (SpadFlimImages.h): per pixel a lifetime by a maximum-
  /// likelihood mono-exponential fit with the instrument's kernel and the
  /// phasor at the laser's repetition frequency (the TDC's range is the
  /// laser period), with a phasor plot. Off: none (and no cost).
  bool flim = false;
  /// Pixels whose histogram (pile-up corrected) holds fewer counts get NaN.
  double flim_min_counts = 100.0;
  std::vector<std::array<int32_t, 2>> plot_pixels;  ///< (x, y) pixels to plot; empty = centre
  std::string colormap = "turbo";
};

/// Expected detections per cycle in each TDC bin of pixel (y, x) if nothing
/// were lost to pile-up or dead time: PDE * (signal * pulse * jitter + ambient)
/// + dark (signal * IRF with an IRF; the pixel's PDE and DCR of its fixed
/// pattern). `axis` is the TDC axis (resolveBins of params.bins). The
/// pixel's own light only: its neighbours' crosstalk is not in it.
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

/// Coates' estimator for a TDC of `stops` stops per cycle (0: every
/// detection) behind a dead time of deadBins bins after each detection (bins
/// j+1 .. j+deadBins, on into the next cycles): flux_i = -ln(1 - h_i / L_i),
/// L_i the cycles live and recording at bin i in expectation: N, less those
/// dead from a detection t = 1 .. deadBins bins before (h_((i - t) mod B):
/// each cycle's detections are distributed as the histogram's), less, with
/// one stop, those that stopped earlier in the cycle. Exact in expectation
/// for unlimited stops, where every avalanche is recorded, and for one stop
/// when no count's dead time reaches the next cycle (then it is
/// coatesEstimate, bit for bit). Otherwise the avalanches after a cycle's
/// last stop, unrecorded, are missing from the histogram with the dead time
/// they cause (and, with 2 or more stops, the cycles that used their last
/// stop before bin i): those cycles count as live, so the flux comes out low
/// where stops run out.
std::vector<double> coatesEstimate(const std::vector<double>& counts, int64_t cycles, int64_t stops,
                                   int32_t deadBins);

/// Whether a detection in `counts` leaves the detector dead into the next
/// cycle (a count in the last deadBins bins).
bool deadTimeReachesNextCycle(const std::vector<double>& counts, int32_t deadBins);

/// Outputs: "spad_counts" Array (H, W, bins); "spad_depth_peak",
/// "spad_depth_coates" and "spad_depth_matched" Images (H, W) in m (plus
/// ColorMappedImages); "spad_intensity" Image (H, W) total counts (plus
/// ColorMappedImage); "spad_confidence" Image (plus ColorMappedImage);
/// "spad_depth_{first,strongest,last}" Images in m (NaN: no return) and
/// "spad_intensity_{first,strongest,last}" in counts, "spad_returns" (how many);
/// every depth Image carries a point cloud (SensorOutput::point_cloud);
/// "spad_histograms" HistogramPlot (pixels, bins); with a fixed pattern
/// (spadHasPixelMaps), "spad_pde_map" and "spad_dcr_map" Images (H, W), with
/// the attributes hot_pixels and dead_pixels; with gate_skew_sigma_s,
/// "spad_gate_skew_map" Image (H, W) in s; with gated_frames,
/// "spad_gated_counts" and "spad_gated_flux" Arrays (H, W, gate_positions);
/// with flim, "spad_lifetime" and "spad_lifetime_sigma" (s), "spad_phasor_g"
/// and "spad_phasor_s" Images (H, W), NaN below flim_min_counts, and the
/// pictures "spad_lifetime" (ns) and "spad_phasor_plot" (SpadFlimImages.h).
std::vector<SensorOutput> runSpad(const TransientVolume& volume, const SpadParams& params,
                                  uint64_t seed);

/// The same model fed as the volume streams (SensorStream.h); spad_counts
/// goes to options.arrays when given. Throws InputError when the parameters
/// do not fit the shape (channel, plot pixels).
std::unique_ptr<SensorStream> openSpad(const SpadParams& params, const VolumeShape& shape,
                                       const StreamOptions& options);

}  // namespace tofsim::sensors
