// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The module's parts, each adding its functions and classes to `m`
// (Module.cpp calls them in this order: later parts take earlier types).

#include <pybind11/pybind11.h>

namespace tetskin::python {

void addSurfaceApi(pybind11::module_& m);     // read_surface, write_surface
void addDatasetApi(pybind11::module_& m);     // Dataset, Level, load_dataset, build
void addBindingApi(pybind11::module_& m);     // Binding, bind, load_binding, deform
void addSimulationApi(pybind11::module_& m);  // Simulation
void addSceneApi(pybind11::module_& m);       // Scene (a Simulation)
void addProbeApi(pybind11::module_& m);       // probe
void addNativeTiming(pybind11::module_& m);   // _native: C++ timings for the overhead benchmark

}  // namespace tetskin::python
