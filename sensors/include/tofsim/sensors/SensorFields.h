#pragma once
// Every sensor parameter, declared once: config key, member, kind, range,
// unit, JSON key and doc (ParamField.h). The config parser, the effective-config
// writer, the key docs (ConfigKeys) and the sensor JSON metadata all visit these
// tables, in this order; defaults are the structs' initialisers. Adding a
// parameter: a member with its default in the params struct, one line here, and
// its use in the model (sensors/README.md, "Adding a parameter").

#include <array>
#include <tuple>

#include "tofsim/sensors/Apd.h"
#include "tofsim/sensors/Common.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/sensors/ParamField.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/sensors/Streak.h"

namespace tofsim::sensors {

// clang-format off
/// SensorCommon::radiometry (`channel` / `channel_weights` are one choice of
/// two keys: hand-written in the config parser, emitter and JSON).
inline constexpr auto kRadiometryFields = std::tuple{
    Field{"source_scale", &Radiometry::source_scale, Number{kNonNegative},
          {.json = "source_scale", .doc = "laser energy per pulse (SPAD, streak) or per exposure (CW-ToF) relative to the render's light"}},
    Field{"etendue", &Radiometry::etendue_m2sr, Number{kPositive},
          {.unit = "m^2 sr", .json = "etendue_m2sr", .doc = "pixel area x solid angle of the aperture"}},
    Field{"optics_transmission", &Radiometry::optics_transmission, Number{kFraction},
          {.json = "optics_transmission", .doc = "lens and filter transmission"}},
    Field{"quantum_efficiency", &Radiometry::quantum_efficiency, Number{kFraction},
          {.json = "quantum_efficiency", .doc = "photo-electrons per photon (leave 1 for SPAD, which has `pde`)"}},
    Field{"wavelength", &Radiometry::wavelength_m, Length{kNonNegative},
          {.json = "wavelength_m", .doc = "0: the volume's values already count photons; > 0: energy is converted to photons with lambda / (h c)"}},
};

/// InstrumentBins of streak and SPAD. The sensor JSON gives the axis resolved
/// against the render instead (bin_width_s, bin_offset_s, bins), so it does
/// not visit this table.
inline constexpr auto kBinsFields = std::tuple{
    Field{"bin_width", &InstrumentBins::bin_width_s, Duration{kPositive},
          {.doc = "instrument bin width", .unset = "the render's"}},
    Field{"bin_offset", &InstrumentBins::offset_s, OptionalDuration{},
          {.doc = "leading edge of bin 0", .unset = "the render's `time.start`"}},
    Field{"bins", &InstrumentBins::count, Integer{},
          {.doc = "number of instrument bins", .unset = "enough to reach the render's end (with the defaults: the render's `time.bins`)"}},
};

inline constexpr auto kStreakFields = std::tuple{
    Custom{"rows", "list of ints", "", "all rows", "pixel", "image rows to record"},
    Field{"row_time", &StreakParams::row_time_s, Duration{kNonNegative},
          {.json = "row_time_s", .doc = "a capture sequence: the rows are scanned one at a time, recorded row i (in `rows` order) taken i row_time after the frame's time; 0: all at once"}},
    Field{"time_fwhm", &StreakParams::time_fwhm_s, Duration{kNonNegative},
          {.json = "time_fwhm_s", .doc = "temporal PSF FWHM (Gaussian)"}},
    Field{"spatial_fwhm", &StreakParams::spatial_fwhm_px, Number{kNonNegative},
          {.unit = "pixel", .json = "spatial_fwhm_px", .doc = "spatial blur FWHM along x (Gaussian)"}},
    Field{"shot_noise", &StreakParams::shot_noise, Flag{},
          {.json = "shot_noise", .doc = "Poisson photo-electron noise"}},
    Field{"read_noise", &StreakParams::read_noise_e, Number{kNonNegative},
          {.unit = "e- RMS", .json = "read_noise_e", .doc = "Gaussian read noise"}},
    Field{"gain", &StreakParams::gain_adu_per_e, Number{kPositive},
          {.unit = "ADU / e-", .json = "gain_adu_per_e", .doc = "output scale"}},
    Field{"saturation", &StreakParams::saturation_adu, Number{kPositive},
          {.unit = "ADU", .json = "saturation_adu", .doc = "clipping level"}},
    Field{"colormap", &StreakParams::colormap, Text{},
          {.json = "colormap", .doc = "colormap of the PNGs"}},
};

inline constexpr std::array<Name<SpadMode>, 2> kSpadModeNames{
    {{"synchronous", SpadMode::Synchronous}, {"free_running", SpadMode::FreeRunning}}};

inline constexpr std::array<Name<SpadAfterpulseCount>, 2> kAfterpulseCountNames{
    {{"bernoulli", SpadAfterpulseCount::Bernoulli}, {"poisson", SpadAfterpulseCount::Poisson}}};
inline constexpr std::array<Name<SpadAfterpulseTraps>, 2> kAfterpulseTrapsNames{
    {{"reset", SpadAfterpulseTraps::Reset}, {"keep", SpadAfterpulseTraps::Keep}}};

inline constexpr std::array<Name<SpadEngine>, 3> kSpadEngineNames{
    {{"auto", SpadEngine::Auto}, {"exact", SpadEngine::Exact}, {"fast", SpadEngine::Fast}}};
inline constexpr std::array<Name<CrosstalkNeighbours>, 2> kCrosstalkNeighbourNames{
    {{"4", CrosstalkNeighbours::Four}, {"8", CrosstalkNeighbours::Eight}}};

inline constexpr auto kSpadFields = std::tuple{
    Custom{"preset", "string", "", "none", "-", "device preset: its published values are the defaults of the other keys (bins included), each explicit key wins (see \"Device presets\" above)"},
    Field{"mode", &SpadParams::mode, Choice<SpadMode>{kSpadModeNames},
          {.json = "mode", .doc = "`synchronous` (first photon, pile-up) or `free_running`"}},
    Field{"cycles", &SpadParams::cycles, Integer{.max = 1'000'000'000'000LL},
          {.json = "cycles", .doc = "laser cycles N"}},
    Field{"exposure_time", &SpadParams::exposure_time_s, Duration{kNonNegative},
          {.json = "exposure_time_s", .doc = "a capture sequence: the cycles spread evenly over this time after the frame's, their flux the mean of the light at `sequence.exposure_samples` times within it; 0: all at the frame's time"}},
    Field{"pulse_fwhm", &SpadParams::pulse_fwhm_s, Duration{kNonNegative},
          {.json = "pulse_fwhm_s", .doc = "Gaussian laser pulse FWHM"}},
    Field{"jitter_fwhm", &SpadParams::jitter_fwhm_s, Duration{kNonNegative},
          {.json = "jitter_fwhm_s", .doc = "Gaussian timing jitter FWHM"}},
    Field{"jitter_tail_fraction", &SpadParams::jitter_tail_fraction, Number{kFraction},
          {.json = "jitter_tail_fraction", .doc = "fraction of detections with an exponential delay"}},
    Field{"jitter_tail", &SpadParams::jitter_tail_s, Duration{kNonNegative},
          {.json = "jitter_tail_s", .doc = "time constant of that delay"}},
    Field{"pde", &SpadParams::pde, Number{kFraction},
          {.json = "pde", .doc = "photon detection efficiency (signal and ambient)"}},
    Field{"ambient_rate", &SpadParams::ambient_rate_per_s, Rate{kNonNegative},
          {.unit = "photons / s", .json = "ambient_rate_per_s", .doc = "ambient photons reaching the pixel (\"2 MHz\" or 2e6)"}},
    Field{"dark_count_rate", &SpadParams::dark_count_rate_per_s, Rate{kNonNegative},
          {.unit = "counts / s", .json = "dark_count_rate_per_s", .doc = "dark counts"}},
    Field{"dead_time", &SpadParams::dead_time_s, Duration{kNonNegative},
          {.json = "dead_time_s", .doc = "dead time after every avalanche, rounded to TDC bins; may span cycles (synchronous: the cycles after a detection it covers are lost)"}},
    Field{"tdc_stops", &SpadParams::tdc_stops, IntegerIn{0, 1'000'000'000},
          {.json = "tdc_stops", .doc = "`synchronous`: detections recorded per cycle (multi-stop TDC), each followed by `dead_time`; later avalanches of the cycle still happen, unrecorded; 0: every one; 1: first photon"}},
    Field{"gate_start", &SpadParams::gate_start_s, Duration{kAnyValue},
          {.json = "gate_start_s", .doc = "time gating: the detector is armed from this time of each cycle (the TDC's time) ..."}},
    Field{"gate_width", &SpadParams::gate_width_s, Duration{kNonNegative},
          {.json = "gate_width_s", .doc = "... for this long; no detection, no pile-up and no dark count outside (a bin the edge crosses counts its armed fraction); 0: ungated. NLOS: gate out the laser spot's first bounce"}},
    Field{"gate_rise", &SpadParams::gate_rise_s, Duration{kNonNegative},
          {.json = "gate_rise_s", .doc = "gate transition: the sensitivity rises linearly from 0 to 1 over this time, centred on `gate_start` (its 10-90 % time is 0.8 of it); 0: a hard edge"}},
    Field{"gate_fall", &SpadParams::gate_fall_s, Duration{kNonNegative},
          {.json = "gate_fall_s", .doc = "the same for the falling edge, centred on `gate_start` + `gate_width` (the ramps must not overlap: `gate_width` >= (`gate_rise` + `gate_fall`) / 2)"}},
    Field{"gate_skew_sigma", &SpadParams::gate_skew_sigma_s, Duration{kNonNegative},
          {.json = "gate_skew_sigma_s", .doc = "per-pixel gate skew: each pixel's gate moved by a Gaussian time of this sigma, a fixed pattern of `fpn_seed` (output `spad_gate_skew_map`); 0: none"}},
    Field{"gated_frames", &SpadParams::gated_frames, IntegerIn{0, 1'000'000'000'000LL},
          {.json = "gated_frames", .doc = "gated 1-bit frames N_f summed per gate position (SPAD512S-class; outputs `spad_gated_counts`, `spad_gated_flux`); needs a gate; 0: off"}},
    Field{"pulses_per_frame", &SpadParams::pulses_per_frame, Integer{.max = 1'000'000'000LL},
          {.json = "pulses_per_frame", .doc = "laser pulses M per 1-bit frame: the latch fires with 1 - exp(-M x the gated flux)"}},
    Field{"gate_step", &SpadParams::gate_step_s, Duration{kAnyValue},
          {.json = "gate_step_s", .doc = "gated frames: the gate moves by this much per position"}},
    Field{"gate_positions", &SpadParams::gate_positions, Integer{.max = 100000},
          {.json = "gate_positions", .doc = "gated frames: gate positions swept (position k: `gate_start` + k `gate_step`)"}},
    Field{"counter_bits", &SpadParams::counter_bits, IntegerIn{0, kMaxCounterBits},
          {.json = "counter_bits", .doc = "counter depth: every count (`spad_counts` bins, gated counts) clips at 2^bits - 1; 0: unlimited"}},
    Custom{"tdc_dnl", "list or file", "", "none (equal bins)", "LSB", "TDC differential non-linearity, one value per bin (each > -1, sum 0): code i is `bin_width` (1 + DNL_i) wide, so pile-up acts on the true unequal bins; a list, or a .npy (1-D float32) or one-column .csv file (see \"TDC non-linearity\" above)"},
    Field{"afterpulse_probability", &SpadParams::afterpulse_probability, Number{kFraction},
          {.json = "afterpulse_probability", .doc = "afterpulses per avalanche: the probability p of one (`bernoulli`) or the mean mu (`poisson`); 0: none. The exact event engine draws such pixels"}},
    Field{"afterpulse_count", &SpadParams::afterpulse_count, Choice<SpadAfterpulseCount>{kAfterpulseCountNames},
          {.json = "afterpulse_count", .doc = "law of the number of afterpulses per avalanche: `bernoulli` (p) or `poisson` (mu)"}},
    Custom{"afterpulse_delay", "duration or list of durations", "> 0", "10 ns", "s", "mean release delay after the end of the dead time: one exponential, or a mixture of exponentials with these means"},
    Custom{"afterpulse_weights", "list of numbers", ">= 0", "equal", "-", "weights of the mixture's exponentials (one per `afterpulse_delay`, any scale)"},
    Custom{"afterpulse_delay_table", "file", "", "none (exponentials)", "s, 1 / s", "measured delay density in place of `afterpulse_delay` and `afterpulse_weights`: a .npy (n, 2) float32 or a two-column .csv of delay (from the end of the dead time, increasing, >= 0) and density (>= 0, any scale); piecewise constant, each row's bin reaching the midpoints to its neighbours; normalised (see \"Afterpulsing\" above)"},
    Field{"afterpulse_traps", &SpadParams::afterpulse_traps, Choice<SpadAfterpulseTraps>{kAfterpulseTrapsNames},
          {.json = "afterpulse_traps", .doc = "`reset`: each avalanche empties the traps of the ones before (the renewal model); `keep`: every release stays pending, lost only if it comes while the detector is dead"}},
    Field{"engine", &SpadParams::engine, Choice<SpadEngine>{kSpadEngineNames},
          {.json = "engine", .doc = "`auto`: the exact event engine for the pixels an effect needs it for (multi-stop, dead time past the cycle, afterpulses) and exact crosstalk where the gate needs it (ramps, skew, a delayed arrival into a gate), the fast draws elsewhere; `exact`: the engine for every pixel, crosstalk exact (see \"Crosstalk\" above); `fast`: afterpulses to first order as extra flux on the fast draws (see \"Afterpulsing\" above)"}},
    Field{"crosstalk_probability", &SpadParams::crosstalk_probability, Number{kFraction},
          {.json = "crosstalk_probability", .doc = "probability that an avalanche triggers one in each neighbouring pixel (first order on the fast path, exact with `engine: exact`, see \"Crosstalk\" above); 0: none"}},
    Field{"crosstalk_neighbours", &SpadParams::crosstalk_neighbours, Choice<CrosstalkNeighbours>{kCrosstalkNeighbourNames},
          {.json = "crosstalk_neighbours", .doc = "`4` (edge neighbours) or `8` (and the diagonal ones), each with `crosstalk_probability`"}},
    Field{"crosstalk_delay", &SpadParams::crosstalk_delay_s, Duration{kNonNegative},
          {.json = "crosstalk_delay_s", .doc = "0: prompt (the neighbour fires in the same bin); else the mean of an exponential delay"}},
    Custom{"irf", "mapping", "", "none (pulse and jitter)", "-", "measured instrument response in place of `pulse_fwhm` and `jitter_*`: `file` (.npy float32, or CSV time,value), `bin_width` (.npy), `t0` (peak, centroid or a time), `floor` (see \"Measured instrument response\" above)"},
    Field{"fpn_seed", &SpadParams::fpn_seed, IntegerIn{0, 4294967295LL},
          {.json = "fpn_seed", .doc = "seed of the array's fixed pattern (below), separate from the noise seed: the same device under every noise seed"}},
    Field{"pde_spread", &SpadParams::pde_spread, Number{kNonNegative},
          {.json = "pde_spread", .doc = "relative sigma of the per-pixel PDE: pde (1 + pde_spread z), clipped to [0, 1]"}},
    Field{"dark_count_log_sigma", &SpadParams::dark_count_log_sigma, Number{kNonNegative},
          {.json = "dark_count_log_sigma", .doc = "sigma of ln DCR per pixel: log-normal with median `dark_count_rate`"}},
    Custom{"dark_count_map", "file", "", "none (log-normal)", "counts / s", "measured dark count rate per pixel, a 2-D float32 .npy of the image's (H, W), in place of the log-normal draw; hot and dead pixels still apply"},
    Field{"hot_pixel_fraction", &SpadParams::hot_pixel_fraction, Number{kFraction},
          {.json = "hot_pixel_fraction", .doc = "fraction of (live) pixels that are hot"}},
    Field{"hot_pixel_rate", &SpadParams::hot_pixel_rate_per_s, Rate{kNonNegative},
          {.unit = "counts / s", .json = "hot_pixel_rate_per_s", .doc = "dark count rate of a hot pixel"}},
    Field{"dead_pixel_fraction", &SpadParams::dead_pixel_fraction, Number{kFraction},
          {.json = "dead_pixel_fraction", .doc = "fraction of pixels that never count (PDE and DCR 0)"}},
    Field{"return_threshold", &SpadParams::return_threshold_sigma, Number{kPositive},
          {.unit = "sigma", .json = "return_threshold_sigma", .doc = "first / strongest / last returns: matched-filter response this many background noise sigmas above the background (see \"Depth estimators and returns\" above)"}},
    Field{"flim", &SpadParams::flim, Flag{},
          {.json = "flim", .doc = "FLIM outputs: `spad_lifetime` (mono-exponential maximum-likelihood fit with the instrument response, s) with `spad_lifetime_sigma`, `spad_phasor_g`, `spad_phasor_s` (IRF-calibrated phasor at the laser's repetition frequency, 1 / the TDC's range) and the picture `spad_phasor_plot` (see \"FLIM: lifetime and phasor\" above)"}},
    Field{"flim_min_counts", &SpadParams::flim_min_counts, Number{kNonNegative},
          {.unit = "counts", .json = "flim_min_counts", .doc = "FLIM: pixels whose histogram (pile-up corrected) holds fewer counts get NaN (counted in the outputs' metadata)"}},
    Custom{"plot_pixels", "list of [x, y]", "", "centre pixel", "pixel", "pixels drawn in `spad_histograms`"},
    Field{"colormap", &SpadParams::colormap, Text{},
          {.json = "colormap", .doc = "colormap of the PNGs"}},
};

inline constexpr std::array<Name<Waveform>, 3> kWaveformNames{
    {{"sine", Waveform::Sine}, {"square", Waveform::Square}, {"measured", Waveform::Measured}}};

inline constexpr std::array<Name<CwTofNoiseModel>, 2> kCwTofNoiseModelNames{
    {{"poisson_read", CwTofNoiseModel::PoissonRead}, {"table", CwTofNoiseModel::Table}}};

inline constexpr auto kCwTofFields = std::tuple{
    Custom{"preset", "string", "", "none", "-", "device preset: its published values are the defaults of the other keys, each explicit key wins (see \"CW-ToF device presets\" below)"},
    Custom{"frequencies", "list of frequencies", "> 0", "[\"20 MHz\"]", "Hz", "modulation frequencies"},
    Field{"phase_steps", &CwTofParams::phase_steps, Integer{.max = 1024, .atLeast = 3},
          {.json = "phase_steps", .doc = "phase steps N per frequency"}},
    Field{"waveform", &CwTofParams::waveform, Choice<Waveform>{kWaveformNames},
          {.json = "waveform", .doc = "`sine`, `square` (50 % duty) or `measured` (the `correlation` waveform)"}},
    Custom{"correlation", "mapping or list of mappings", "", "none", "-", "measured correlation waveform (`waveform: measured`): `harmonics` (list of [re, im], c_1..c_K), `samples` (M values at phases 2 pi j / M) or `file` (.csv phase_rad,value or 1-D float32 .npy); one for all frequencies or a list of one per frequency (see \"Measured correlation waveforms\" below)"},
    Field{"modulation_contrast", &CwTofParams::modulation_contrast, Number{Range{.min = 0.0, .max = 1.0, .minExclusive = true}},
          {.json = "modulation_contrast", .doc = "m: the AC part of every raw image is scaled by m (0.5 m E rho)"}},
    Field{"ambient", &CwTofParams::ambient_e, Number{kNonNegative},
          {.unit = "e-", .json = "ambient_e", .doc = "ambient photo-electrons per raw image and pixel"}},
    Field{"shot_noise", &CwTofParams::shot_noise, Flag{},
          {.json = "shot_noise", .doc = "Poisson noise on the raw images"}},
    Field{"read_noise", &CwTofParams::read_noise_e, Number{kNonNegative},
          {.unit = "e- RMS", .json = "read_noise_e", .doc = "Gaussian read noise per raw image"}},
    Field{"max_depth", &CwTofParams::max_depth_m, Length{kNonNegative},
          {.json = "max_depth_m", .doc = "unwrapping search range", .note = "automatic"}},
    Field{"colormap", &CwTofParams::colormap, Text{},
          {.json = "colormap", .doc = "colormap of the PNGs"}},
    Field{"multipath_by_order", &CwTofParams::multipath_by_order, Flag{},
          {.json = "multipath_by_order", .doc = "also the depth error of direct + bounces 1..k against the ground truth for every order k = 0..N (`cwtof_multipath_error_by_order`); needs `output.depth` and a renderer that resolves bounces (see \"Multipath error by bounce order\" above)"}},
    // The device stage (see "Raw frames as a device delivers them" below): all off by default.
    Field{"fpn_seed", &CwTofParams::fpn_seed, IntegerIn{0, 4294967295LL},
          {.json = "fpn_seed", .doc = "seed of the fixed pattern (delay, gains, offsets), separate from the noise seed: the same device under every noise seed"}},
    Field{"delay_sigma", &CwTofParams::delay_sigma_s, Duration{kNonNegative},
          {.json = "delay_sigma_s", .doc = "per-pixel time offset delta_p, Gaussian of this sigma (fixed pattern): each bin's phase interval shifted by 2 pi f delta_p inside the correlation (output `cwtof_delay_map`); 0: none"}},
    Custom{"delay_map", "file", "", "none", "s", "measured delta_p per pixel, a 2-D float32 .npy of the image's (H, W), in place of `delay_sigma`"},
    Field{"gain_sigma", &CwTofParams::gain_sigma, Number{kNonNegative},
          {.json = "gain_sigma", .doc = "relative sigma of each tap's per-pixel gain (fixed pattern): tap gain (1 + gain_sigma z), on the light before its shot noise (outputs `cwtof_gain_map`, `cwtof_gain_map_b`)"}},
    Custom{"gain_map", "file", "", "none", "-", "measured relative gain per pixel (both taps), a 2-D float32 .npy (H, W) of values >= 0, in place of `gain_sigma`"},
    Field{"offset_sigma", &CwTofParams::offset_sigma_e, Number{kNonNegative},
          {.unit = "e-", .json = "offset_sigma_e", .doc = "per-pixel offset added to every raw, Gaussian of this sigma (fixed pattern; output `cwtof_offset_map`)"}},
    Custom{"offset_map", "file", "", "none", "e-", "measured raw offset per pixel, a 2-D float32 .npy (H, W), in place of `offset_sigma`"},
    Field{"taps", &CwTofParams::taps, IntegerIn{1, 2},
          {.json = "taps", .doc = "1: each raw is one tap's charge; 2: tap A integrates the correlation at theta, tap B at theta + pi, the raw is A - B"}},
    Field{"tap_a_gain", &CwTofParams::tap_a_gain, Number{kPositive},
          {.json = "tap_a_gain", .doc = "gain of tap A (of the one tap with `taps: 1`), on the light before its shot noise"}},
    Field{"tap_b_gain", &CwTofParams::tap_b_gain, Number{kPositive},
          {.json = "tap_b_gain", .doc = "gain of tap B (`taps: 2`)"}},
    Field{"output_taps", &CwTofParams::output_taps, Flag{},
          {.json = "output_taps", .doc = "also each tap's charge, `cwtof_raw_taps` (F, N, 2, H, W) e- (`taps: 2`)"}},
    Field{"ambient_suppression", &CwTofParams::ambient_suppression, Number{kFraction},
          {.json = "ambient_suppression", .doc = "beta: beta min(A, B) of common-mode charge removed from both taps before the full well, its shot noise kept (`taps: 2`); 0: none"}},
    Field{"dark_current", &CwTofParams::dark_current_e, Number{kNonNegative},
          {.unit = "e-", .json = "dark_current_e", .doc = "dark electrons per tap and raw, Poisson with the light"}},
    Field{"full_well", &CwTofParams::full_well_e, Number{kNonNegative},
          {.unit = "e-", .json = "full_well_e", .doc = "full well per tap, before the difference: a tap at or above it holds it and the pixel is saturated (NaN `cwtof_device_depth`, `cwtof_saturated`)", .note = "none"}},
    Field{"adc_bits", &CwTofParams::adc_bits, IntegerIn{0, 24},
          {.json = "adc_bits", .doc = "ADC: DN = clamp(round(adc_gain x + adc_offset), 0, 2^bits - 1) (`cwtof_raw_dn`, `cwtof_device_*`); 0: no ADC"}},
    Field{"adc_gain", &CwTofParams::adc_gain_dn_per_e, Number{kPositive},
          {.unit = "DN / e-", .json = "adc_gain_dn_per_e", .doc = "conversion gain G of the ADC"}},
    Field{"adc_offset", &CwTofParams::adc_offset_dn, Number{kAnyValue},
          {.unit = "DN", .json = "adc_offset_dn", .doc = "ADC offset (the device subtracts it before its phases)"}},
    Custom{"companding", "list of [in, out] or file", "", "none (linear)", "DN", "piecewise-linear companding of the ADC's linear value before rounding: points [input DN, output DN] (inputs increasing, outputs not decreasing), a list or a two-column .csv; outside its inputs the raw clips (saturated)"},
    Custom{"capture_order", "list of [f, n]", "", "frequency-major", "-", "the order the raws are taken in, every [frequency index, phase step] once; gives each raw's start time in the sensor JSON (`capture.raw_start_times_s`)"},
    Field{"integration_time", &CwTofParams::integration_time_s, Duration{kNonNegative},
          {.json = "integration_time_s", .doc = "exposure of one raw (time stamps: raw i of the capture order starts at i (integration_time + readout_gap))"}},
    Field{"readout_gap", &CwTofParams::readout_gap_s, Duration{kNonNegative},
          {.json = "readout_gap_s", .doc = "dead time between two raws (time stamps)"}},
    Field{"noise_model", &CwTofParams::noise_model, Choice<CwTofNoiseModel>{kCwTofNoiseModelNames},
          {.json = "noise_model", .doc = "`poisson_read` (`shot_noise`, `read_noise`) or `table`: an empirical conditional noise table (`noise_table`) in place of both"}},
    Custom{"noise_table", "file", "", "none", "e-", "`noise_model: table`: rows (integer noise-free raw, measured raw), a two-column .csv or a float32 .npy (n, 2); a raw whose noise-free value rounds to a listed mean becomes one of its samples, drawn uniformly; elsewhere it is noise-free"},
};
inline constexpr std::array<Name<ApdThreshold>, 3> kApdThresholdNames{
    {{"cfar", ApdThreshold::Cfar}, {"fixed", ApdThreshold::Fixed}, {"ca_cfar", ApdThreshold::CaCfar}}};

/// The linear-mode APD (Apd.h). Defaults: a 905 nm Si APD receiver
/// (sensors/README.md, "Linear-mode APD", lists each value's source).
inline constexpr auto kApdFields = std::tuple{
    Field{"gain", &ApdParams::gain, Number{Range{.min = 1.0}},
          {.json = "gain", .doc = "mean avalanche gain M"}},
    Field{"ionization_ratio", &ApdParams::ionization_ratio, Number{kFraction},
          {.json = "ionization_ratio", .doc = "k, hole / electron ionisation ratio: excess noise F(M) = k M + (1 - k)(2 - 1/M) (McIntyre)"}},
    Field{"background_rate", &ApdParams::background_rate, Rate{kNonNegative},
          {.unit = "photo-electrons / s", .json = "background_rate_per_s", .doc = "ambient light's primary photo-electrons (sunlight through the filter), multiplied with the signal"}},
    Field{"dark_current_bulk", &ApdParams::dark_current_bulk_A, Number{kNonNegative},
          {.unit = "A", .json = "dark_current_bulk_A", .doc = "primary bulk dark current, multiplied (M x it at the output)"}},
    Field{"dark_current_surface", &ApdParams::dark_current_surface_A, Number{kNonNegative},
          {.unit = "A", .json = "dark_current_surface_A", .doc = "surface dark current, not multiplied"}},
    Field{"tia_noise", &ApdParams::tia_noise_A_per_rtHz, Number{kNonNegative},
          {.unit = "A / sqrt(Hz)", .json = "tia_noise_A_per_rtHz", .doc = "transimpedance amplifier's input-referred current noise density (thermal)"}},
    Field{"bandwidth", &ApdParams::bandwidth_Hz, Rate{kNonNegative},
          {.unit = "Hz", .json = "bandwidth_Hz", .doc = "receiver's -3 dB bandwidth, a Gaussian low-pass filter on the current and its noise; 0: none (white samples)"}},
    Field{"pulse_fwhm", &ApdParams::pulse_fwhm_s, Duration{kNonNegative},
          {.json = "pulse_fwhm_s", .doc = "the laser pulse's FWHM (Gaussian), on the signal"}},
    Field{"adc_bits", &ApdParams::adc_bits, IntegerIn{0, 24},
          {.json = "adc_bits", .doc = "ADC depth: samples round to adc_full_scale / 2^bits, clipped to [0, full scale); 0: none"}},
    Field{"adc_full_scale", &ApdParams::adc_full_scale_A, Number{kPositive},
          {.unit = "A", .json = "adc_full_scale_A", .doc = "the ADC's range in input current"}},
    Field{"threshold_mode", &ApdParams::threshold_mode, Choice<ApdThreshold>{kApdThresholdNames},
          {.json = "threshold_mode", .doc = "`cfar`: the threshold the background noise crosses with `false_alarm` per sample (its mean + z sigma); `ca_cfar`: cell-averaging CFAR, per sample its training cells' mean + z kappa sigma(that mean), `false_alarm` per sample on a linear background (see CA-CFAR below); `fixed`: `threshold`"}},
    Field{"threshold", &ApdParams::threshold_A, Number{kAnyValue},
          {.unit = "A", .json = "threshold_A", .doc = "`threshold_mode: fixed`: an echo is a run of samples above this current"}},
    Field{"false_alarm", &ApdParams::false_alarm, Number{Range{.min = 0.0, .max = 0.5, .minExclusive = true}},
          {.json = "false_alarm", .doc = "`threshold_mode: cfar` or `ca_cfar`: the probability that a sample of background alone is above the threshold"}},
    Field{"guard_cells", &ApdParams::cfar_guard_cells, IntegerIn{0, 1024},
          {.json = "cfar_guard_cells", .doc = "`threshold_mode: ca_cfar`: samples left out on each side of the sample tested (an echo's own width)"}},
    Field{"training_cells", &ApdParams::cfar_training_cells, IntegerIn{1, 4096},
          {.json = "cfar_training_cells", .doc = "`threshold_mode: ca_cfar`: samples averaged on each side beyond the guard cells (fewer at the axis' ends)"}},
    Field{"max_returns", &ApdParams::max_returns, Integer{.max = 64},
          {.json = "max_returns", .doc = "echoes kept per pixel (beam), in time order"}},
    Field{"output_waveforms", &ApdParams::output_waveforms, Flag{},
          {.json = "output_waveforms", .doc = "write `apd_waveforms` (H, W, T), the noisy digitised current"}},
    Field{"colormap", &ApdParams::colormap, Text{},
          {.json = "colormap", .doc = "colormap of the PNGs"}},
};
// clang-format on

}  // namespace tofsim::sensors
