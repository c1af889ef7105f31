#pragma once
// Private to the config module: a measured scattering-delay kernel, issue
// 41's `scattering_delay: {model: table, file: kernel.csv, delay_unit: ns}`
// (core/physics/temporal_response.md): the file's rows (delay, weight), read
// and checked as every delay table is (DelayTableFile.h), become the
// temporal-response stage's table kernel, a piecewise-linear density
// through the points, normalised (physics::ResponseModel::Table). Delays are
// in `delay_unit` (s, ms, us, ns or ps; default s, as the config's other
// table files: an IRF's CSV times, an afterpulse table's delays), from the
// light's arrival at the surface (>= 0); weights any scale. The material
// table reads `model` and `fraction` and calls this for `model: table`;
// whether the kernel fits the render's axis (kMaxResponseTaps bins) is
// checked where the axis is known.

#include "ConfigNode.h"
#include "tofsim/physics/TemporalResponse.h"

namespace tofsim::config {

/// `file` and `delay_unit` of the mapping n as a table kernel; its
/// `fraction` is left at 1 (the caller's key).
physics::ResponseKernel parseResponseTable(const ConfigNode& n);

}  // namespace tofsim::config
