#pragma once
// Private to the Python module: one sensor on a volume already in memory,
// as Python objects (SenseBinding.cpp): tofsim.sense's and a kept
// renderer's sensors (RenderBinding.cpp) share it.

#include <pybind11/pybind11.h>

#include "tofsim/sensors/SensorInputs.h"
#include "tofsim/sensors/SensorSpec.h"

namespace tofsim::python {

/// (outputs: name -> float32 array, metadata: name -> JSON text (the CLI's
/// sensors/<name>/<output>.json without `files`), warnings). Releases the
/// GIL while the model runs.
pybind11::tuple senseInputs(const sensors::SensorSpec& spec, const sensors::SensorInputs& inputs);

}  // namespace tofsim::python
