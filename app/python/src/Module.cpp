// SPDX-License-Identifier: AGPL-3.0-or-later
// The tetskin module's C++ part, tetskin._tetskin (doc/user/python.md):
// tetskin.Error and the parts of the API (Api.h).
#include <pybind11/pybind11.h>

#include "Api.h"
#include "tetskin/core/Error.h"

namespace py = pybind11;

PYBIND11_MODULE(_tetskin, m) {
  m.doc() = "TetSkin: multiresolution deformable bodies with bound high-resolution surfaces";
  m.attr("__version__") = TETSKIN_VERSION;
  // One error type for everything TetSkin refuses, with the message the
  // command line prints after "error: ". It is a ValueError (bad input) and
  // a RuntimeError (a step that blew up) both, so either except clause takes it.
  static py::handle error = PyErr_NewExceptionWithDoc(
      "tetskin.Error",
      "What TetSkin refuses: a malformed file, a bad argument, a simulation that blew up. "
      "The message is the one `tetskin` prints.",
      py::make_tuple(py::handle(PyExc_ValueError), py::handle(PyExc_RuntimeError)).release().ptr(),
      nullptr);
  m.add_object("Error", error);
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const tetskin::Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    }
  });
  tetskin::python::addSurfaceApi(m);
  tetskin::python::addDatasetApi(m);
  tetskin::python::addBindingApi(m);
  tetskin::python::addSimulationApi(m);
  tetskin::python::addSceneApi(m);
  tetskin::python::addProbeApi(m);
  tetskin::python::addNativeTiming(m);
}
