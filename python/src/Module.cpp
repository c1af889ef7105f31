// The native half of the Python package `tofsim` (python/tofsim/__init__.py
// is the public face).

#include "Bindings.h"

PYBIND11_MODULE(_tofsim, m) {
  m.doc() = "tofsim native bindings; use the `tofsim` package";
  tofsim::python::bindErrors(m);
  tofsim::python::bindConfig(m);
  tofsim::python::bindRender(m);
  tofsim::python::bindSense(m);
}
