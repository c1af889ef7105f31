#include "CwTofDeviceImages.h"

#include <algorithm>
#include <limits>
#include <string>

#include "CwTofOutputs.h"
#include "tofsim/sensors/CwTofDevice.h"

namespace tofsim::sensors {

CwTofDeviceImages::CwTofDeviceImages(const CwTofParams& p, std::size_t pixels)
    : p_(p),
      HW_(pixels),
      FN_(p.frequencies_Hz.size() * p.phase_steps),
      adc_(p.adc_bits > 0),
      flagged_(p.adc_bits > 0 || p.full_well_e > 0.0) {
  const std::size_t F = p.frequencies_Hz.size();
  if (adc_) {
    dn_.resize(FN_ * HW_);
    phase_.resize(F * HW_);
    amplitude_.resize(F * HW_);
    depth_.resize(HW_);
  }
  if (flagged_) saturated_.resize(HW_);
  if (p.output_taps) {
    taps_.resize(2 * FN_ * HW_);
    scratchTaps_.resize(2 * FN_);
  }
}

void CwTofDeviceImages::pixel(std::size_t px, const std::vector<double>& raw_e, bool saturated,
                              const Correlator& correlator, double unwrapRange_m) {
  for (std::size_t j = 0; j < taps_.size() / HW_; ++j) taps_[j * HW_ + px] = float(scratchTaps_[j]);
  if (adc_) {
    code_.resize(FN_);
    for (std::size_t j = 0; j < FN_; ++j) {
      const double dn = cwtofAdc(p_, raw_e[j], saturated);
      dn_[j * HW_ + px] = static_cast<float>(dn);
      code_[j] = dn - p_.adc_offset_dn;  // the device's zero
    }
    const double depth = correlator.depth(code_, phases_, amps_, unwrapRange_m);
    depth_[px] = saturated ? std::numeric_limits<float>::quiet_NaN() : static_cast<float>(depth);
    for (std::size_t f = 0; f < phases_.size(); ++f) {
      phase_[f * HW_ + px] = static_cast<float>(phases_[f]);
      amplitude_[f * HW_ + px] = static_cast<float>(amps_[f]);
    }
  }
  if (flagged_) saturated_[px] = saturated ? 1.0f : 0.0f;
}

void CwTofDeviceImages::add(std::vector<SensorOutput>& outs, int32_t H, int32_t W,
                            double depthRange_m, const CwTofFixedPattern& pattern) {
  const auto F = static_cast<int64_t>(p_.frequencies_Hz.size());
  const int64_t N = p_.phase_steps;
  const std::string& cmap = p_.colormap;
  if (!taps_.empty()) {
    outs.push_back(makeOutput("cwtof_raw_taps", SensorOutput::Kind::Array, {F, N, 2, H, W},
                              {"frequency", "phase_step", "tap", "y", "x"}, std::move(taps_),
                              "photo-electrons",
                              "CW-ToF charge of each tap as read, before the difference "
                              "(frequency, phase step, tap, y, x)"));
  }
  if (adc_ && !p_.capture_order.empty()) {
    // The same DN raws as the device streams them: raw i of the capture
    // order is plane i, so a decoder written for the device reads them as is.
    const std::vector<CwTofCaptureStep> order = cwtofCaptureOrder(p_);
    std::vector<float> sequence(FN_ * HW_);
    for (std::size_t i = 0; i < order.size(); ++i) {
      const auto j = static_cast<std::size_t>(order[i].frequency * N + order[i].step);
      std::copy_n(dn_.begin() + static_cast<std::ptrdiff_t>(j * HW_), HW_,
                  sequence.begin() + static_cast<std::ptrdiff_t>(i * HW_));
    }
    outs.push_back(makeOutput(
        "cwtof_raw_sequence", SensorOutput::Kind::Array, {static_cast<int64_t>(FN_), H, W},
        {"capture_index", "y", "x"}, std::move(sequence), "DN",
        "CW-ToF raws after the ADC in capture order (capture index, y, x): plane i is "
        "capture_order[i] of the sensor JSON's capture.order"));
  }
  if (adc_) {
    outs.push_back(makeOutput("cwtof_raw_dn", SensorOutput::Kind::Array, {F, N, H, W},
                              {"frequency", "phase_step", "y", "x"}, std::move(dn_), "DN",
                              "CW-ToF raws after the ADC, " + std::to_string(p_.adc_bits) +
                                  " bits (frequency, phase "
                                  "step, y, x)"));
    outs.push_back(makeOutput("cwtof_device_phase", SensorOutput::Kind::Array, {F, H, W},
                              {"frequency", "y", "x"}, std::move(phase_), "rad",
                              "CW-ToF wrapped phase per frequency from the DN raws, [0, 2 pi)"));
    addImage(
        outs, "cwtof_device_depth", H, W, std::move(depth_), "m",
        "CW-ToF depth from the DN raws (NaN where a raw saturated), range " + metres(depthRange_m),
        cmap, {{{"range_m", depthRange_m}}, false});
    outs[outs.size() - 2].point_cloud = SensorOutput::PointCloud{"cwtof_device_amplitude", ""};
    addImage(outs, "cwtof_device_amplitude", H, W,
             {amplitude_.begin(), amplitude_.begin() + static_cast<std::ptrdiff_t>(HW_)}, "DN",
             "CW-ToF amplitude from the DN raws at the first frequency", cmap,
             {{{"frequency_Hz", p_.frequencies_Hz[0]}}, false});
  }
  if (flagged_) {
    addImage(outs, "cwtof_saturated", H, W, std::move(saturated_), "-",
             "CW-ToF saturation: 1 where a tap reached the full well or a raw clipped in the ADC",
             cmap);
  }
  const auto map = [&](const char* name, const std::vector<double>& values, const char* unit,
                       const char* what) {
    if (values.empty()) return;
    addImage(outs, name, H, W, {values.begin(), values.end()}, unit, what, cmap);
  };
  if (!cwtofHasFixedPattern(p_)) return;
  map("cwtof_delay_map", pattern.delay_s, "s", "CW-ToF fixed-pattern time offset per pixel");
  map("cwtof_offset_map", pattern.offset_e, "photo-electrons",
      "CW-ToF fixed-pattern raw offset per pixel");
  if (!(p_.gain_sigma > 0.0 || p_.gain_map.present())) return;
  map("cwtof_gain_map", pattern.gain_a, "-", "CW-ToF gain of tap A per pixel");
  map("cwtof_gain_map_b", pattern.gain_b, "-", "CW-ToF gain of tap B per pixel");
}

}  // namespace tofsim::sensors
