// SPDX-License-Identifier: AGPL-3.0-or-later
// read_surface and write_surface: the surface files `tetskin` reads and
// writes (.obj, .ply, .stl, .vtp), as NumPy arrays.
#include <pybind11/stl/filesystem.h>

#include "Api.h"
#include "ArrayConversion.h"
#include "tetskin/vtkio/SurfaceFile.h"

namespace tetskin::python {

void addSurfaceApi(py::module_& m) {
  m.def(
      "read_surface",
      [](const std::filesystem::path& path) {
        SurfaceMesh mesh;
        {
          py::gil_scoped_release unlocked;
          mesh = readSurface(path);
        }
        return py::make_tuple(owning(std::move(mesh.positions)), owning(std::move(mesh.triangles)));
      },
      py::arg("path"),
      "The surface in `path` (.obj, .ply, .stl, .vtp) as (V, F): vertex positions, float64 "
      "(n, 3), and triangles, int32 (m, 3), counter-clockwise seen from outside.");
  m.def(
      "write_surface",
      [](const std::filesystem::path& path, py::handle V, py::handle F) {
        SurfaceMesh mesh;
        mesh.positions = points3(V, "V");
        mesh.triangles = intRows(F, "F", 3);
        validateSurface(mesh, "(V, F)");
        py::gil_scoped_release unlocked;
        writeSurface(path, mesh);
      },
      py::arg("path"), py::arg("V"), py::arg("F"),
      "Writes the surface (V float (n, 3), F int (m, 3)) to `path` (.obj, .ply, .stl or .vtp "
      "by its extension), through a temporary file: a failed write leaves no partial file.");
}

}  // namespace tetskin::python
