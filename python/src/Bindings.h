#pragma once
// Private to the Python module: each file binds one part of the pipeline.

#include <pybind11/pybind11.h>

#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::python {

/// An InputError's message without its "loc: key: " prefix.
std::string inputErrorMessage(const InputError& e);

/// tofsim.ConfigError and the C++ -> Python exception translation.
void bindErrors(pybind11::module_& m);
/// Config (a validated RunConfig) and the loaders.
void bindConfig(pybind11::module_& m);
/// _render: a config rendered into NumPy arrays (and files, when asked).
void bindRender(pybind11::module_& m);
/// _sense: one sensor model on any transient array.
void bindSense(pybind11::module_& m);

}  // namespace tofsim::python
