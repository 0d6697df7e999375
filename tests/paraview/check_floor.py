# Opens a `tetskin simulate` run with ParaView's own PVD reader and checks
# the floor its control frames record, as field data a researcher sees in
# ParaView's information panel: FloorNormal (the up axis) and FloorHeight.
# Usage: check_floor.py RUN.pvd NX NY NZ HEIGHT, or RUN.pvd none for a run
# without a floor.
import sys

from paraview import servermanager
from paraview.simple import OpenDataFile


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def first_grid(data):
    if data.IsA("vtkMultiBlockDataSet"):
        for i in range(data.GetNumberOfBlocks()):
            grid = first_grid(data.GetBlock(i))
            if grid is not None:
                return grid
        return None
    return data if data is not None and data.IsA("vtkUnstructuredGrid") else None


reader = OpenDataFile(sys.argv[1])
for time in (reader.TimestepValues[0], reader.TimestepValues[-1]):
    reader.UpdatePipeline(time)
    grid = first_grid(servermanager.Fetch(reader))
    if grid is None:
        fail("no control mesh in the run")
    normal = grid.GetFieldData().GetArray("FloorNormal")
    height = grid.GetFieldData().GetArray("FloorHeight")
    if sys.argv[2] == "none":
        if normal is not None or height is not None:
            fail("a run without a floor records one")
        continue
    if normal is None or height is None:
        fail("FloorNormal or FloorHeight missing at t = %g" % time)
    expected = tuple(float(v) for v in sys.argv[2:5])
    if normal.GetTuple3(0) != expected:
        fail("FloorNormal %s, expected %s" % (normal.GetTuple3(0), expected))
    if abs(height.GetTuple1(0) - float(sys.argv[5])) > 1e-9:
        fail("FloorHeight %g, expected %s" % (height.GetTuple1(0), sys.argv[5]))
print("PASS: the floor as recorded")
