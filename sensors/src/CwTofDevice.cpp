#include "tofsim/sensors/CwTofDevice.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "CwTofDeviceStage.h"
#include "tofsim/sensors/CwTof.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors {

namespace {
constexpr uint32_t kCwTofPatternTag = 0x4346;  // "CF": its own stream per pixel of fpn_seed

void checkMapShape(const CwTofPixelMap& map, const char* key, int32_t height, int32_t width) {
  if (map.present() && (map.height != height || map.width != width ||
                        map.values.size() != static_cast<std::size_t>(height) * width)) {
    throw InputError("cwtof " + std::string(key) + " " + map.file + " is " +
                     std::to_string(map.height) + " x " + std::to_string(map.width) +
                     " (H x W) but the image is " + std::to_string(height) + " x " +
                     std::to_string(width));
  }
}

/// The piecewise-linear companding curve at v (DN); outside its inputs the
/// end output, and `clipped`.
double compand(const CwTofCompanding& c, double v, bool& clipped) {
  const std::vector<double>&x = c.input_dn, &y = c.output_dn;
  if (v < x.front() || v > x.back()) {
    clipped = true;
    return v < x.front() ? y.front() : y.back();
  }
  const auto upper = std::upper_bound(x.begin(), x.end(), v);
  if (upper == x.end()) return y.back();
  const std::size_t i = static_cast<std::size_t>(upper - x.begin());
  return y[i - 1] + (v - x[i - 1]) * ((y[i] - y[i - 1]) / (x[i] - x[i - 1]));
}
}  // namespace

const std::vector<double>* CwTofNoiseTable::at(double raw_e) const {
  const double i = std::round(raw_e) - static_cast<double>(first_mean_e);
  if (!(i >= 0.0 && i < static_cast<double>(samples.size()))) return nullptr;
  const std::vector<double>& set = samples[static_cast<std::size_t>(i)];
  return set.empty() ? nullptr : &set;
}

bool cwtofHasFixedPattern(const CwTofParams& p) {
  return p.delay_sigma_s > 0.0 || p.delay_map.present() || p.gain_sigma > 0.0 ||
         p.gain_map.present() || p.offset_sigma_e > 0.0 || p.offset_map.present();
}

bool cwtofDeviceActive(const CwTofParams& p) {
  return cwtofHasFixedPattern(p) || p.taps != 1 || p.tap_a_gain != 1.0 || p.tap_b_gain != 1.0 ||
         p.ambient_suppression > 0.0 || p.dark_current_e > 0.0 || p.full_well_e > 0.0 ||
         p.adc_bits > 0 || p.noise_model != CwTofNoiseModel::PoissonRead;
}

CwTofFixedPattern cwtofFixedPattern(const CwTofParams& p, int32_t height, int32_t width) {
  checkMapShape(p.delay_map, "delay_map", height, width);
  checkMapShape(p.gain_map, "gain_map", height, width);
  checkMapShape(p.offset_map, "offset_map", height, width);
  const std::size_t n = static_cast<std::size_t>(height) * static_cast<std::size_t>(width);
  CwTofFixedPattern fp;
  const bool delay = p.delay_sigma_s > 0.0 || p.delay_map.present();
  const bool offset = p.offset_sigma_e > 0.0 || p.offset_map.present();
  if (delay) fp.delay_s.resize(n);
  fp.gain_a.resize(n);
  if (p.taps == 2) fp.gain_b.resize(n);
  if (offset) fp.offset_e.resize(n);
  for (std::size_t px = 0; px < n; ++px) {
    // Four normals in a fixed order whichever keys are set, so changing one
    // sigma leaves the others' pattern as it was.
    Rng rng(static_cast<uint64_t>(p.fpn_seed), pixelStream(kCwTofPatternTag, px));
    const double zDelay = rng.normal(), zGainA = rng.normal(), zGainB = rng.normal(),
                 zOffset = rng.normal();
    const double measuredGain = p.gain_map.present() ? p.gain_map.values[px] : 1.0;
    if (delay) {
      fp.delay_s[px] = p.delay_map.present() ? p.delay_map.values[px] : p.delay_sigma_s * zDelay;
    }
    fp.gain_a[px] = p.tap_a_gain * (1.0 + p.gain_sigma * zGainA) * measuredGain;
    if (p.taps == 2) fp.gain_b[px] = p.tap_b_gain * (1.0 + p.gain_sigma * zGainB) * measuredGain;
    if (offset) {
      fp.offset_e[px] =
          p.offset_map.present() ? p.offset_map.values[px] : p.offset_sigma_e * zOffset;
    }
  }
  return fp;
}

std::vector<CwTofCaptureStep> cwtofCaptureOrder(const CwTofParams& p) {
  if (!p.capture_order.empty()) return p.capture_order;
  std::vector<CwTofCaptureStep> order;
  for (int32_t f = 0; f < static_cast<int32_t>(p.frequencies_Hz.size()); ++f) {
    for (int32_t n = 0; n < p.phase_steps; ++n) order.push_back({f, n});
  }
  return order;
}

std::vector<double> cwtofRawStartTimes_s(const CwTofParams& p) {
  const std::vector<CwTofCaptureStep> order = cwtofCaptureOrder(p);
  std::vector<double> start(p.frequencies_Hz.size() * p.phase_steps, 0.0);
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::size_t j = static_cast<std::size_t>(order[i].frequency) * p.phase_steps +
                          static_cast<std::size_t>(order[i].step);
    TOFSIM_CHECK(j < start.size());
    start[j] = static_cast<double>(i) * (p.integration_time_s + p.readout_gap_s);
  }
  return start;
}

double cwtofAdc(const CwTofParams& p, double raw_e, bool& saturated) {
  TOFSIM_CHECK(p.adc_bits > 0 && p.adc_bits <= 24);
  double v = p.adc_gain_dn_per_e * raw_e + p.adc_offset_dn;
  if (p.companding.present()) v = compand(p.companding, v, saturated);
  const double code = std::round(v);
  const double hi = std::ldexp(1.0, p.adc_bits) - 1.0;
  if (code < 0.0 || code > hi) saturated = true;
  return std::clamp(code, 0.0, hi);
}

void checkCwTofDevice(const CwTofParams& p) {
  const auto fail = [](const std::string& what) { throw InputError("cwtof " + what); };
  if (p.taps != 1 && p.taps != 2) fail("taps must be 1 or 2 (got " + std::to_string(p.taps) + ")");
  if (p.adc_bits < 0 || p.adc_bits > 24) {
    fail("adc_bits must be in [0, 24] (got " + std::to_string(p.adc_bits) + ")");
  }
  if (!(p.ambient_suppression >= 0.0 && p.ambient_suppression <= 1.0)) {
    fail("ambient_suppression must be in [0, 1]");
  }
  if (p.ambient_suppression > 0.0 && p.taps != 2) fail("ambient_suppression needs taps: 2");
  if (p.output_taps && p.taps != 2) fail("output_taps needs taps: 2");
  if (!(p.adc_gain_dn_per_e > 0.0)) fail("adc_gain must be > 0");
  if ((p.companding.present() || p.adc_gain_dn_per_e != 1.0 || p.adc_offset_dn != 0.0) &&
      p.adc_bits == 0) {
    fail("adc_gain, adc_offset and companding need adc_bits (the ADC is off at 0)");
  }
  const CwTofCompanding& c = p.companding;
  if (c.input_dn.size() != c.output_dn.size() || (c.present() && c.input_dn.size() < 2)) {
    fail("companding needs at least 2 points of (input, output)");
  }
  for (std::size_t i = 1; i < c.input_dn.size(); ++i) {
    if (!(c.input_dn[i] > c.input_dn[i - 1]) || c.output_dn[i] < c.output_dn[i - 1]) {
      fail("companding point " + std::to_string(i) +
           ": inputs must increase and outputs must not decrease");
    }
  }
  const bool table = p.noise_model == CwTofNoiseModel::Table;
  if (table != p.noise_table.present()) {
    fail(table ? "noise_model: table needs a noise_table"
               : "noise_table is for noise_model: table");
  }
  if (table && p.read_noise_e > 0.0) fail("read_noise is part of the noise_table: remove it");
  const std::size_t F = p.frequencies_Hz.size(), N = static_cast<std::size_t>(p.phase_steps);
  if (!p.capture_order.empty()) {
    std::vector<bool> seen(F * N, false);
    for (const CwTofCaptureStep& s : p.capture_order) {
      if (s.frequency < 0 || s.step < 0 || static_cast<std::size_t>(s.frequency) >= F ||
          static_cast<std::size_t>(s.step) >= N) {
        fail("capture_order [" + std::to_string(s.frequency) + ", " + std::to_string(s.step) +
             "] is not a (frequency, phase step) of " + std::to_string(F) + " x " +
             std::to_string(N));
      }
      const std::size_t j = static_cast<std::size_t>(s.frequency) * N + s.step;
      if (seen[j]) {
        fail("capture_order lists [" + std::to_string(s.frequency) + ", " + std::to_string(s.step) +
             "] twice");
      }
      seen[j] = true;
    }
    if (p.capture_order.size() != F * N) {
      fail("capture_order lists " + std::to_string(p.capture_order.size()) + " raws of " +
           std::to_string(F * N) + " (every (frequency, phase step) once)");
    }
  }
  if (!(p.full_well_e >= 0.0 && p.dark_current_e >= 0.0 && p.gain_sigma >= 0.0 &&
        p.delay_sigma_s >= 0.0 && p.offset_sigma_e >= 0.0 && p.integration_time_s >= 0.0 &&
        p.readout_gap_s >= 0.0 && p.tap_a_gain > 0.0 && p.tap_b_gain > 0.0)) {
    fail(
        "device parameters out of range (sigmas, full well, dark current, times >= 0, tap gains > "
        "0)");
  }
}

// --- the stage of one pixel ------------------------------------------------------

CwTofDeviceStage::CwTofDeviceStage(const CwTofParams& p, int32_t height, int32_t width)
    : p_((checkCwTofDevice(p), p)), pattern_(cwtofFixedPattern(p, height, width)) {}

double CwTofDeviceStage::draw(double mean, Rng& rng) const {
  return p_.shot_noise ? static_cast<double>(rng.poisson(std::max(0.0, mean))) : mean;
}

double CwTofDeviceStage::well(double charge, bool& saturated) const {
  if (p_.full_well_e > 0.0 && charge >= p_.full_well_e) {
    saturated = true;
    return p_.full_well_e;
  }
  return charge;
}

bool CwTofDeviceStage::pixel(std::vector<double>& v, std::size_t px, Rng& rng, double* taps) const {
  if (p_.noise_model == CwTofNoiseModel::Table) return tablePixel(v, px, rng, taps);
  const std::size_t FN = p_.frequencies_Hz.size() * p_.phase_steps;
  const double gA = pattern_.gain_a[px];
  const double offset = pattern_.offset_e.empty() ? 0.0 : pattern_.offset_e[px];
  const double dark = p_.dark_current_e;
  bool saturated = false;
  // Each branch only where set, so that with every default the arithmetic
  // (and the bytes) are the ideal model's.
  const auto mean = [&](double clean, double g) {
    if (g != 1.0) clean *= g;
    if (dark > 0.0) clean += dark;
    return clean;
  };
  const auto read = [&](double& charge) {
    if (p_.read_noise_e > 0.0) charge += rng.normal(0.0, p_.read_noise_e);
  };
  if (p_.taps != 2) {
    for (std::size_t j = 0; j < FN; ++j) {
      double a = well(draw(mean(v[j], gA), rng), saturated);
      read(a);
      if (taps) taps[j] = a;
      v[j] = offset != 0.0 ? a + offset : a;
    }
    return saturated;
  }
  const double gB = pattern_.gain_b[px];
  for (std::size_t j = 0; j < FN; ++j) {
    double a = draw(mean(v[j], gA), rng);
    double b = draw(mean(v[FN + j], gB), rng);
    if (p_.ambient_suppression > 0.0) {  // in-pixel: the well does not hold it
      const double common = p_.ambient_suppression * std::min(a, b);
      a -= common;
      b -= common;
    }
    a = well(a, saturated);
    b = well(b, saturated);
    read(a);
    read(b);
    if (taps) {
      taps[2 * j] = a;
      taps[2 * j + 1] = b;
    }
    v[j] = a - b + offset;
  }
  v.resize(FN);
  return saturated;
}

// The same charges without noise, then one draw of the table per raw.
bool CwTofDeviceStage::tablePixel(std::vector<double>& v, std::size_t px, Rng& rng,
                                  double* taps) const {
  const std::size_t FN = p_.frequencies_Hz.size() * p_.phase_steps;
  const int32_t T = p_.taps == 2 ? 2 : 1;
  const double offset = pattern_.offset_e.empty() ? 0.0 : pattern_.offset_e[px];
  bool saturated = false;
  for (std::size_t j = 0; j < FN; ++j) {
    double charge[2] = {0.0, 0.0};
    for (int32_t t = 0; t < T; ++t) {
      const double g = t == 0 ? pattern_.gain_a[px] : pattern_.gain_b[px];
      charge[t] = g * v[t * FN + j] + p_.dark_current_e;
    }
    if (T == 2 && p_.ambient_suppression > 0.0) {
      const double common = p_.ambient_suppression * std::min(charge[0], charge[1]);
      charge[0] -= common;
      charge[1] -= common;
    }
    for (int32_t t = 0; t < T; ++t) {
      charge[t] = well(charge[t], saturated);
      if (taps) taps[T * j + t] = charge[t];
    }
    const double clean = charge[0] - charge[1] + offset;
    const std::vector<double>* set = p_.noise_table.at(clean);
    const double u = rng.uniform();  // one per raw, drawn or not
    v[j] =
        set ? (*set)[std::min(set->size() - 1, static_cast<std::size_t>(u * set->size()))] : clean;
  }
  v.resize(FN);
  return saturated;
}

}  // namespace tofsim::sensors
