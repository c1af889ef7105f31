#pragma once
// CW-ToF raw frames as a camera delivers them: the device stage between the
// noise-free correlation and the phases (per-pixel fixed pattern, one or two
// taps, ambient suppression, shot, read and dark noise, full well, ADC with
// companding, saturation) and the capture order with each raw's time stamp.
// Every part is off by default: the raws are then the ideal model's, byte for
// byte. Model and keys: sensors/README.md, "Raw frames as a device delivers
// them".

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tofsim::sensors {

struct CwTofParams;

/// A per-pixel map (H, W), row-major, read by the config layer from a 2-D
/// float32 .npy; its shape is checked against the image.
struct CwTofPixelMap {
  std::string file;  ///< the file it came from (metadata)
  int32_t height = 0, width = 0;
  std::vector<double> values;  ///< finite; empty: none

  bool present() const { return !values.empty(); }
};

/// A piecewise-linear companding curve: the ADC's linear value (DN) at
/// input_dn[i] becomes output_dn[i]; inputs increase strictly, outputs do not
/// decrease. Outside [input_dn.front(), input_dn.back()] the value clips to
/// the end outputs and the raw is flagged saturated.
struct CwTofCompanding {
  std::string file;  ///< empty: an inline list in the config
  std::vector<double> input_dn, output_dn;

  bool present() const { return !input_dn.empty(); }
};

/// The noise of the raws: Poisson shot noise per tap and Gaussian read noise,
/// or an empirical conditional table (FLAT's approach).
enum class CwTofNoiseModel { PoissonRead, Table };

/// An empirical conditional noise table: for integer noise-free raw values
/// first_mean_e + i, the measured raws samples[i] (empty: no noise there).
/// A raw whose noise-free value rounds to a mean with samples becomes one of
/// them, drawn uniformly; outside the table it is the noise-free value.
struct CwTofNoiseTable {
  std::string file;
  int64_t first_mean_e = 0;
  std::vector<std::vector<double>> samples;

  bool present() const { return !samples.empty(); }
  /// The samples of the mean nearest to `raw_e`, or nullptr.
  const std::vector<double>* at(double raw_e) const;
};

/// One raw of the capture: frequency index f and phase step n.
struct CwTofCaptureStep {
  int32_t frequency = 0;
  int32_t step = 0;
  bool operator==(const CwTofCaptureStep&) const = default;
};

/// The fixed pattern of the array, per pixel (row-major): drawn from fpn_seed
/// alone (its own stream per pixel, four normals in a fixed order: delay,
/// gain of tap A, gain of tap B, offset), or read from the maps.
struct CwTofFixedPattern {
  std::vector<double> delay_s;   ///< time offset delta_p, s (0 without one)
  std::vector<double> gain_a;    ///< tap A gain: tap_a_gain (1 + gain_sigma z) x gain_map
  std::vector<double> gain_b;    ///< tap B gain (taps: 2), likewise with tap_b_gain
  std::vector<double> offset_e;  ///< offset added to every raw, e-
};

/// True when any part of the device stage is set (otherwise the raws are the
/// ideal model's, with its Poisson and read noise only).
bool cwtofDeviceActive(const CwTofParams& p);
/// True when a fixed-pattern key (a sigma or a map) is set.
bool cwtofHasFixedPattern(const CwTofParams& p);

/// Throws InputError for device parameters that do not fit (taps, adc_bits,
/// a companding curve that is not increasing, a capture order that is not a
/// permutation of every (f, n), a key that needs another).
void checkCwTofDevice(const CwTofParams& p);

/// The fixed pattern of a height x width array. Throws InputError when a map
/// does not have the image's shape.
CwTofFixedPattern cwtofFixedPattern(const CwTofParams& p, int32_t height, int32_t width);

/// The capture order: capture_order, or frequency-major, step-minor.
std::vector<CwTofCaptureStep> cwtofCaptureOrder(const CwTofParams& p);

/// Each raw's start time (F, N) row-major, s from the first raw's start: raw
/// i of the capture order starts at i (integration_time + readout_gap).
std::vector<double> cwtofRawStartTimes_s(const CwTofParams& p);

/// The ADC of one raw x (e-): v = adc_gain x + adc_offset (DN), through the
/// companding curve when there is one, rounded half away from zero and
/// clamped to [0, 2^adc_bits - 1]; `saturated` is set (never cleared) when
/// the value clipped. adc_bits > 0.
double cwtofAdc(const CwTofParams& p, double raw_e, bool& saturated);

}  // namespace tofsim::sensors
