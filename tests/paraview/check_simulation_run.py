# Opens a `tetskin simulate --surface` run with ParaView's own PVD reader and
# checks what a researcher would look at: time steps, arrays, value ranges.
# Usage: check_simulation_run.py RUN.pvd EXPECTED_FRAMES LEVEL
import sys

from paraview import servermanager
from paraview.simple import OpenDataFile
from pvcheck import fail, leaves


def array_range(data, association, name, component=-1):
    arrays = data.GetPointData() if association == "point" else data.GetCellData()
    array = arrays.GetArray(name)
    if array is None:
        fail("array %s (%s) missing in %s" % (name, association, data.GetClassName()))
    return array.GetRange(component)


pvd, frames, level = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
reader = OpenDataFile(pvd)
times = list(reader.TimestepValues)
if len(times) != frames:
    fail("expected %d time steps, found %d" % (frames, len(times)))
if times != sorted(times) or times[0] != 0.0:
    fail("time steps are not ascending from 0: %s" % times)

for index, time in enumerate([times[0], times[-1]]):
    reader.UpdatePipeline(time)
    data = servermanager.Fetch(reader)
    blocks = leaves(data)
    grids = [b for b in blocks if b.IsA("vtkUnstructuredGrid")]
    surfaces = [b for b in blocks if b.IsA("vtkPolyData")]
    if len(grids) != 1 or len(surfaces) != 1:
        fail("expected one control mesh and one surface per step, got %s" % [b.GetClassName() for b in blocks])
    grid, surface = grids[0], surfaces[0]
    if grid.GetNumberOfCells() == 0 or grid.GetCellType(0) != 10:  # VTK_TETRA
        fail("the control mesh has no tetrahedra")
    displacement = array_range(grid, "point", "Displacement")
    array_range(grid, "point", "Velocity")
    stress = array_range(grid, "cell", "VonMisesStress")
    levels = array_range(grid, "cell", "Level")
    ratio = array_range(grid, "cell", "VolumeRatio")
    # The wobble pushes sideways (x) only; nothing acts before the first step.
    push = array_range(grid, "point", "ExternalForce", 0)
    for component in (1, 2):
        if array_range(grid, "point", "ExternalForce", component) != (0.0, 0.0):
            fail("ExternalForce has a component %d: the wobble pushes along x only" % component)
    if index == 0 and push != (0.0, 0.0):
        fail("ExternalForce before the first step: %s" % (push,))
    if index == 1 and not (push[0] < 0.0 or push[1] > 0.0):
        fail("ExternalForce: no push in the last frame")
    # The wobble holds its base still and leaves the rest free.
    if array_range(grid, "point", "Prescribed") != (0.0, 1.0):
        fail("Prescribed should be 1 at the held base and 0 elsewhere, ranges %s"
             % (array_range(grid, "point", "Prescribed"),))
    # The supports' reactions: zero at the free nodes; at the start (at
    # rest) each held node carries its own weight, straight up (y); once the
    # body is pushed sideways the base holds it back along x too.
    reactions = grid.GetPointData().GetArray("ReactionForce")
    prescribed = grid.GetPointData().GetArray("Prescribed")
    if reactions is None or reactions.GetNumberOfComponents() != 3:
        fail("ReactionForce (3 components per point) missing")
    sideways = 0.0
    for p in range(grid.GetNumberOfPoints()):
        r = reactions.GetTuple3(p)
        if prescribed.GetTuple1(p) == 0.0:
            if r != (0.0, 0.0, 0.0):
                fail("ReactionForce %s at the free point %d" % (r, p))
        elif index == 0 and not (r[1] > 0.0 and abs(r[0]) + abs(r[2]) < 1e-6 * r[1]):
            fail("ReactionForce %s at held point %d at rest: not its weight, up" % (r, p))
        sideways = max(sideways, abs(r[0]))
    if index == 1 and not sideways > 0.0:
        fail("ReactionForce: the base does not hold the pushed body back along x")
    if levels != (level, level):
        fail("Level should be %d everywhere, is %s" % (level, levels))
    if index == 0 and displacement[1] != 0.0:
        fail("the first frame should be the rest state, max |displacement| %g" % displacement[1])
    if index == 1 and not displacement[1] > 0.0:
        fail("the last frame has not moved")
    if index == 1 and not (stress[1] > 0.0 and ratio[0] > 0.0):
        fail("stress %s or volume ratio %s out of range" % (stress, ratio))
    weights = surface.GetPointData().GetArray("Weights")
    if weights is None or weights.GetNumberOfComponents() != 3:
        fail("surface Weights missing")
    for p in range(0, surface.GetNumberOfPoints(), 97):
        if abs(sum(weights.GetTuple3(p)) - 1.0) > 1e-9:
            fail("weights of surface point %d do not sum to 1" % p)
    for name in ("ControlIds", "Distance", "MinBarycentric", "FaceId", "Normals"):
        if surface.GetPointData().GetArray(name) is None:
            fail("surface array %s missing" % name)
    # The surface's own displacement from its rest shape, as the control
    # mesh's (to rounding at the start: the rest is rebuilt from the weights).
    moved = array_range(surface, "point", "Displacement")
    if index == 0 and not moved[1] < 1e-9:
        fail("the first surface frame should be at rest, max |Displacement| %g" % moved[1])
    if index == 1 and not moved[1] > 0.0:
        fail("the last surface frame has not moved")
    pose = surface.GetFieldData().GetAbstractArray("Pose")
    if pose is None or pose.GetValue(0) != "deformed":
        fail("the surface frames should have field data Pose 'deformed'")
    normals = array_range(surface, "point", "Normals", -1)
    if abs(normals[1] - 1.0) > 1e-6:
        fail("surface normals are not unit length: %s" % (normals,))

print("PASS: %d time steps, control mesh and surface arrays as expected" % len(times))
