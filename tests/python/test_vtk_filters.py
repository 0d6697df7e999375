# SPDX-License-Identifier: AGPL-3.0-or-later
"""The VTK filters in a pipeline of Debian's python3-vtk9 objects, against
the command line's binding and tetskin.deform."""
import numpy as np
import pytest

import tetskin
from conftest import DATA, rotation

pytest.importorskip("vtkmodules.vtkCommonDataModel")
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import VTK_TETRA, vtkCellArray, vtkUnstructuredGrid  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader  # noqa: E402

from tetskin import vtk as tsvtk  # noqa: E402


def grid(nodes, elements):
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(nodes), deep=True))
    cells = vtkCellArray()
    cells.SetData(numpy_to_vtkIdTypeArray(np.arange(0, 4 * len(elements) + 1, 4), deep=True),
                  numpy_to_vtkIdTypeArray(elements.astype(np.int64).ravel(), deep=True))
    g = vtkUnstructuredGrid()
    g.SetPoints(points)
    g.SetCells(VTK_TETRA, cells)
    return g


def point_array(data, name):
    return vtk_to_numpy(data.GetPointData().GetArray(name))


def surface_reader(tmp_path):
    """The 8k bunny from a .vtp (in doubles: VTK's OBJ reader reads floats)."""
    tetskin.write_surface(tmp_path / "bunny_8k.vtp", *tetskin.read_surface(DATA / "bunny_8k.obj"))
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(tmp_path / "bunny_8k.vtp"))
    return reader


def test_bind_and_deform_filters_match_the_command_and_the_module(tmp_path, cli, bunny):
    level = bunny.level(1)
    reader = surface_reader(tmp_path)
    bind = tsvtk.vtkTetSkinBindSurface()
    bind.SetInputConnection(reader.GetOutputPort())
    bind.SetControlMeshData(grid(level.nodes, level.elements))
    bind.SetMethodToClosest()
    bind.Update()
    bound = bind.GetOutput()
    assert bound.GetNumberOfPoints() == 4001

    cli("bind", DATA / "bunny.json", DATA / "bunny_8k.obj", "--level", 1, "-o", tmp_path / "b.vtp")
    binding = tetskin.load_binding(tmp_path / "b.vtp")
    ids = point_array(bound, "ControlIds")
    np.testing.assert_array_equal(ids[:, :3], binding.control_ids - level.first_node)
    np.testing.assert_array_equal(point_array(bound, "Weights")[:, :3], binding.weights)
    np.testing.assert_array_equal(point_array(bound, "Distance"), binding.distance)

    moved = level.nodes @ rotation(0.4).T + [1.0, 2.0, 0.0]
    deform = tsvtk.vtkTetSkinDeformSurface()
    deform.SetInputConnection(bind.GetOutputPort())
    deform.SetControlMeshData(grid(moved, level.elements))
    deform.Update()
    V, N = tetskin.deform(binding, moved)
    out = deform.GetOutput()
    np.testing.assert_array_equal(vtk_to_numpy(out.GetPoints().GetData()), V)
    np.testing.assert_array_equal(point_array(out, "Normals"), N)


def test_a_filter_with_bad_input_reports_an_error_and_gives_nothing(tmp_path):
    bind = tsvtk.vtkTetSkinBindSurface()
    reader = surface_reader(tmp_path)
    bind.SetInputConnection(reader.GetOutputPort())
    bind.SetControlMeshData(vtkUnstructuredGrid())  # no tetrahedra
    bind.GlobalWarningDisplayOff()
    bind.Update()
    assert bind.GetOutput().GetNumberOfPoints() == 0
