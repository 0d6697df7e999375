// SPDX-License-Identifier: AGPL-3.0-or-later
// probe: a recorded run read at points, as `tetskin probe` reads it
// (RunProbe.h), as NumPy arrays.
#include <pybind11/stl/filesystem.h>

#include "Api.h"
#include "ArrayConversion.h"
#include "tetskin/session/RunProbe.h"

namespace tetskin::python {

void addProbeApi(py::module_& m) {
  m.def(
      "probe",
      [](const std::filesystem::path& run, py::handle points) {
        const Points3 at = points3(points, "points");
        std::vector<std::string> names;
        for (Index p = 0; p < at.rows(); ++p) names.push_back("points[" + std::to_string(p) + "]");
        RunProbe probe;
        {
          py::gil_scoped_release unlocked;
          probe = probeRun(run, at, names);
        }
        const auto frames = static_cast<py::ssize_t>(probe.times.size());
        const auto count = static_cast<py::ssize_t>(at.rows());
        const bool stressed = !probe.stresses.empty() && probe.stresses.front().rows() > 0;
        py::array_t<double> displacement({frames, count, py::ssize_t{3}});
        py::array_t<double> stress({frames, stressed ? count : py::ssize_t{0}, py::ssize_t{6}});
        py::array_t<double> vonMises({frames, count});
        auto d = displacement.mutable_unchecked<3>();
        auto s = stress.mutable_unchecked<3>();
        auto v = vonMises.mutable_unchecked<2>();
        for (py::ssize_t f = 0; f < frames; ++f)
          for (py::ssize_t p = 0; p < count; ++p) {
            const auto frame = static_cast<std::size_t>(f);
            for (py::ssize_t c = 0; c < 3; ++c) d(f, p, c) = probe.displacements[frame](p, c);
            if (stressed)
              for (py::ssize_t c = 0; c < 6; ++c) s(f, p, c) = probe.stresses[frame](p, c);
            v(f, p) = probe.vonMises[frame][p];
          }
        py::dict out;
        out["times"] = py::array_t<double>(frames, probe.times.data());
        out["elements"] = py::array_t<int>(count, probe.elements.data());
        out["displacement"] = displacement;
        out["stress"] = stress;
        out["von_mises"] = vonMises;
        return out;
      },
      py::arg("run"), py::arg("points"),
      "A recorded run (.pvd) read at `points` (float (k, 3), the rest shape's coordinates), as "
      "`tetskin probe` reads it: a dict of `times` (f,), `elements` (k,: the tetrahedron each "
      "point lies in), `displacement` (f, k, 3: interpolated in it, m), `stress` (f, k, 6: "
      "its tetrahedron's, Pa, xx, yy, zz, xy, yz, xz; (f, 0, 6) for a run recorded without "
      "it) and `von_mises` (f, k). Raises tetskin.Error naming points[i] for a point outside "
      "the control mesh.");
}

}  // namespace tetskin::python
