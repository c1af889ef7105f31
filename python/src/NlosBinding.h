#pragma once
// Private to the Python module: _render's half for nlos configs.

#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "tofsim/config/RunConfig.h"

namespace tofsim::python {

/// H, its format, the grids, the origins, the time axis and stats; releases
/// the GIL while rendering.
pybind11::dict renderNlos(const config::RunConfig& config,
                          const std::optional<std::string>& outputDir, bool quiet);

}  // namespace tofsim::python
