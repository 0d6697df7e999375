# SPDX-License-Identifier: AGPL-3.0-or-later
"""TetSkin's VTK filters in VTK's Python (Debian's python3-vtk9):

    from tetskin import vtk as tsvtk
    bind = tsvtk.vtkTetSkinBindSurface()
    bind.SetInputConnection(surface_reader.GetOutputPort())
    bind.SetControlMeshConnection(level_reader.GetOutputPort())

They take and give VTK's own objects, in any pipeline; their inputs and
outputs are those of the ParaView plugin's Bind Surface and Deform Surface
(doc/user/paraview.md).
"""

# The wrapped classes' base classes first, as VTK's own modules import theirs.
import vtkmodules.vtkCommonExecutionModel  # noqa: F401

from .vtkTetSkinFilters import vtkTetSkinBindSurface, vtkTetSkinDeformSurface

__all__ = ["vtkTetSkinBindSurface", "vtkTetSkinDeformSurface"]
