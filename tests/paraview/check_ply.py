# Opens a PLY written by `tetskin convert` with ParaView's own reader, as a
# user would, and checks what TetSkin wrote: counts, exact positions
# (doubles) and the texture coordinates. Prints PASS: on success.
import sys

from paraview import servermanager as sm
from paraview.simple import OpenDataFile

path, vertices, triangles = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
reader = OpenDataFile(path)
reader.UpdatePipeline()
data = sm.Fetch(reader)
assert data.GetNumberOfPoints() == vertices, data.GetNumberOfPoints()
assert data.GetNumberOfCells() == triangles, data.GetNumberOfCells()
coords = data.GetPointData().GetTCoords()
assert coords is not None and coords.GetNumberOfTuples() == vertices, "no texture coordinates"
u, v = coords.GetRange(0), coords.GetRange(1)
assert 0 <= u[0] <= u[1] <= 1 and 0 <= v[0] <= v[1] <= 1, (u, v)
print("PASS: %d points, %d triangles, u %s, v %s" % (vertices, triangles, u, v))
