# SPDX-License-Identifier: AGPL-3.0-or-later
"""TetSkin from Python: datasets, binding, deformation and simulation over
the same libraries as the ``tetskin`` command line, with NumPy arrays.

    import tetskin
    dataset = tetskin.load_dataset("data/bunny.json")
    V, F = tetskin.read_surface("data/bunny_64k.obj")
    binding = tetskin.bind(dataset, V, F)
    sim = tetskin.Simulation(dataset, scenario="wobble")
    sim.step(100)
    V2, N2 = tetskin.deform(binding, sim.positions)

Errors raise tetskin.Error with the message the command line prints. The
VTK filters are in tetskin.vtk (VTK's Python). See doc/user/python.md.
"""

from ._tetskin import (
    Binding,
    Dataset,
    Error,
    Level,
    Scene,
    Simulation,
    __version__,
    bind,
    build,
    deform,
    load_binding,
    load_dataset,
    probe,
    read_surface,
    write_surface,
)

__all__ = [
    "Binding",
    "Dataset",
    "Error",
    "Level",
    "Scene",
    "Simulation",
    "bind",
    "build",
    "deform",
    "load_binding",
    "load_dataset",
    "probe",
    "read_surface",
    "write_surface",
]
