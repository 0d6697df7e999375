// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin._tetskin._native: the C++ calls behind deform and
// Simulation.step, timed in C++ on the same objects, so that
// tests/python/bench_overhead.py can measure what calling through Python
// adds, in the same run. Not part of the API.
#include <chrono>

#include "Api.h"
#include "ArrayConversion.h"
#include "Objects.h"

namespace tetskin::python {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

void addNativeTiming(py::module_& m) {
  py::module_ native = m.def_submodule("_native", "C++ timings for bench_overhead.py");
  native.def(
      "deform_seconds",
      [](BindingObject& b, py::handle controlPositions, int calls) {
        const Points3 control = points3(controlPositions, "control_positions");
        py::gil_scoped_release unlocked;
        std::lock_guard lock(b.deforming);
        SurfaceDeformer& deformer = b.madeDeformer();
        // As a C++ caller deforms each frame: its output rows kept between
        // frames (and between calls here).
        static thread_local Points3 positions, normals;
        const Clock::time_point start = Clock::now();
        for (int i = 0; i < calls; ++i) deformer.deform(control, positions, normals);
        return secondsSince(start) / calls;
      },
      "Seconds per SurfaceDeformer::deform of all dataset nodes (out rows reused).");
  native.def(
      "step_seconds",
      [](SimulationObject& s, int steps) {
        py::gil_scoped_release unlocked;
        std::lock_guard lock(s.changing);
        const Clock::time_point start = Clock::now();
        for (int i = 0; i < steps; ++i) s.session->step();
        return secondsSince(start) / steps;
      },
      "Seconds per SimulationSession::step, `steps` steps.");
}

}  // namespace tetskin::python
