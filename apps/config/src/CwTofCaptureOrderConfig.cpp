#include "CwTofCaptureOrderConfig.h"

#include <optional>
#include <string>
#include <vector>

#include "tofsim/sensors/CwTofCaptureOrder.h"
#include "tofsim/sensors/CwTofPresets.h"

namespace tofsim::config {

namespace {
using sensors::CwTofCaptureStep;
using sensors::CwTofParams;

// The preset's own parameters (its frequencies, steps and order), or none.
std::optional<CwTofParams> presetParams(const CwTofParams& p) {
  if (p.preset.empty()) return std::nullopt;
  const sensors::CwTofPreset* preset = sensors::findCwTofPreset(p.preset);
  if (!preset) return std::nullopt;
  CwTofParams own;
  preset->apply(own);
  if (own.capture_order.empty()) return std::nullopt;
  return own;
}

std::optional<std::vector<CwTofCaptureStep>> derived(const CwTofParams& preset,
                                                     const CwTofParams& p) {
  return sensors::deriveCwTofCaptureOrder(
      preset.capture_order, static_cast<int32_t>(preset.frequencies_Hz.size()),
      preset.phase_steps, static_cast<int32_t>(p.frequencies_Hz.size()), p.phase_steps);
}

std::string raws(const CwTofParams& p) {
  return std::to_string(p.frequencies_Hz.size()) + " frequencies x " +
         std::to_string(p.phase_steps) + " steps";
}
}  // namespace

void derivePresetCaptureOrder(const ConfigNode& n, CwTofParams& p) {
  if (n.has("capture_order")) return;
  const std::optional<CwTofParams> preset = presetParams(p);
  if (!preset) return;
  if (preset->frequencies_Hz.size() == p.frequencies_Hz.size() &&
      preset->phase_steps == p.phase_steps) {
    return;  // the preset's own raws: its own order (set by the preset)
  }
  if (auto order = derived(*preset, p)) {
    p.capture_order = std::move(*order);
    return;
  }
  CwTofParams plain = p;
  plain.capture_order.clear();
  n.failKey(n.has("frequencies") ? "frequencies" : "phase_steps",
            "gives " + raws(p) + ", and preset '" + p.preset + "''s capture order " +
                sensors::cwtofCaptureOrderText(preset->capture_order) + " (" + raws(*preset) +
                ") does not carry over to them (configs/README.md, `capture_order`): set "
                "`capture_order`, every [frequency index, phase step] once in the order the "
                "raws are taken, e.g. " +
                sensors::cwtofCaptureOrderText(sensors::cwtofCaptureOrder(plain)));
}

std::string suggestedCaptureOrder(const CwTofParams& p) {
  if (const std::optional<CwTofParams> preset = presetParams(p)) {
    if (auto order = derived(*preset, p)) return sensors::cwtofCaptureOrderText(*order);
  }
  CwTofParams plain = p;
  plain.capture_order.clear();
  return sensors::cwtofCaptureOrderText(sensors::cwtofCaptureOrder(plain));
}

}  // namespace tofsim::config
