# Opens a `tetskin compare` series with ParaView's own PVD reader: a surface
# per compared level at every time step, each with the error and stress
# arrays, the reference's errors zero and another level's not.
# Usage: check_compare.py OUT.pvd EXPECTED_FRAMES LEVELS REFERENCE_PART
import sys

from paraview import servermanager
from paraview.simple import OpenDataFile
from pvcheck import fail, leaves


pvd, frames, levels, reference = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
reader = OpenDataFile(pvd)
times = list(reader.TimestepValues)
if len(times) != frames:
    fail("expected %d time steps, found %d" % (frames, len(times)))
reader.UpdatePipeline(times[-1])
surfaces = leaves(servermanager.Fetch(reader))
if len(surfaces) != levels or not all(s.IsA("vtkPolyData") for s in surfaces):
    fail("expected %d surfaces, got %s" % (levels, [s.GetClassName() for s in surfaces]))
for part, surface in enumerate(surfaces):
    for name in ("SurfaceError", "RelativeError", "NormalAngle", "VonMisesStress",
                 "EquivalentStrain", "Normals", "Displacement"):
        if surface.GetPointData().GetArray(name) is None:
            fail("part %d lacks the point array %s" % (part, name))
    largest = surface.GetPointData().GetArray("SurfaceError").GetRange()[1]
    stress = surface.GetPointData().GetArray("VonMisesStress").GetRange()[1]
    if part == reference and largest != 0.0:
        fail("the reference's SurfaceError reaches %g" % largest)
    if part != reference and not largest > 0.0:
        fail("part %d has no error against the reference" % part)
    if not stress > 0.0:
        fail("part %d carries no stress" % part)
print("PASS: %d time steps of %d surfaces with their errors and stress" % (len(times), levels))
