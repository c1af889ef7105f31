// tofsim's two error channels in Python: InputError (bad input: a config
// value, a missing file, a sensor that does not fit the volume) becomes
// tofsim.ConfigError, a ValueError carrying the location and key; Interrupted
// becomes KeyboardInterrupt. Programmer bugs (TOFSIM_CHECK) still abort.

#include <string>

#include "Bindings.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"

namespace py = pybind11;

namespace tofsim::python {

// what() is "loc: key: message"; the message alone is what is left.
std::string inputErrorMessage(const InputError& e) {
  std::string text = e.what();
  const std::string where = e.location().toString();
  if (!where.empty() && text.compare(0, where.size() + 2, where + ": ") == 0) {
    text.erase(0, where.size() + 2);
  }
  if (!e.key().empty() && text.compare(0, e.key().size() + 2, e.key() + ": ") == 0) {
    text.erase(0, e.key().size() + 2);
  }
  return text;
}

namespace {
py::object optionalText(const std::string& s) {
  return s.empty() ? py::object(py::none()) : py::object(py::str(s));
}
py::object optionalInt(int v) { return v > 0 ? py::object(py::int_(v)) : py::object(py::none()); }

void raiseConfigError(const py::object& type, const InputError& e) {
  py::object error = type(e.what());
  error.attr("file") = optionalText(e.location().file);
  error.attr("line") = optionalInt(e.location().line);
  error.attr("column") = optionalInt(e.location().column);
  error.attr("key") = optionalText(e.key());
  error.attr("message") = inputErrorMessage(e);
  PyErr_SetObject(type.ptr(), error.ptr());
}
}  // namespace

void bindErrors(py::module_& m) {
  // Created here rather than in Python so that the translator, which runs
  // without the package imported, can reach it.
  static py::handle configError =
      PyErr_NewExceptionWithDoc("tofsim.ConfigError",
                                "Bad input: a config value, a missing file, a sensor that does not "
                                "fit. Attributes: file, line, column (None when unknown), key "
                                "(the key path, e.g. 'camera.fov_y'), message.",
                                PyExc_ValueError, nullptr);
  m.attr("ConfigError") = py::reinterpret_borrow<py::object>(configError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      raiseConfigError(py::reinterpret_borrow<py::object>(configError), e);
    } catch (const Interrupted& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    }
  });
}

}  // namespace tofsim::python
