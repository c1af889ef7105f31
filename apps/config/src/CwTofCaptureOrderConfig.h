#pragma once
// Private to the config module: a CW-ToF preset's capture order where the
// config changes its frequencies or phase steps. No `capture_order` (or
// `capture_order: null`) derives it by the rule of sensors'
// CwTofCaptureOrder.h; one that cannot be derived, and `capture_order: []`,
// are located errors that show an order to write.

#include "ConfigNode.h"
#include "tofsim/sensors/CwTof.h"

namespace tofsim::config {

/// After every key is read: where p's preset fixes a capture order and the
/// config gives none, the order for p's frequencies and steps (the preset's
/// own when they are the preset's). Throws a located error at `frequencies`
/// or `phase_steps` when it cannot be derived.
void derivePresetCaptureOrder(const ConfigNode& n, sensors::CwTofParams& p);

/// An order to write for p's frequencies and steps, as a config writes it:
/// the preset's carried over where it can be, else frequency-major.
std::string suggestedCaptureOrder(const sensors::CwTofParams& p);

}  // namespace tofsim::config
