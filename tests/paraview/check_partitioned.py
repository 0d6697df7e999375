# A run's surface written in pieces (`tetskin deform --positions RUN.pvd
# --pieces N`: a .pvtp per frame) opened by ParaView's own readers, as a
# user would, on one rank (pvpython) or several (`mpiexec -n RANKS
# pvbatch`, each rank reading its pieces): gathered, every triangle is
# there once and every point, matched by its GlobalPointIds, has the
# position and arrays of the same run written whole (no --pieces).
# Usage: check_partitioned.py PIECES.pvd WHOLE.pvd PIECES RANKS
import sys

from paraview import servermanager
from paraview.simple import PVDReader, ProcessIdScalars
from pvcheck import fail, leaves

pieces_pvd, whole_pvd, pieces, ranks = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
partitions = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
if partitions != ranks:
    fail("runs on %d ranks, expected %d (is pvbatch started by mpiexec?)" % (partitions, ranks))

split_reader = PVDReader(FileName=pieces_pvd)
whole_reader = PVDReader(FileName=whole_pvd)
times = list(whole_reader.TimestepValues)
if list(split_reader.TimestepValues) != times or len(times) < 2:
    fail("the series have times %s and %s" % (list(split_reader.TimestepValues), times))
split = ProcessIdScalars(Input=split_reader)
NAMES = ("Normals", "Displacement", "ControlIds", "Weights")


def fetch(proxy, time):
    proxy.UpdatePipeline(time)
    return [d for d in leaves(servermanager.Fetch(proxy)) if d.GetNumberOfPoints() > 0]


def column(data, name):
    array = data.GetPointData().GetArray(name)
    if array is None:
        fail("a piece lacks the point array %s" % name)
    return [array.GetTuple(i) for i in range(array.GetNumberOfTuples())]


for time in (times[0], times[-1]):
    whole = fetch(whole_reader, time)
    if len(whole) != 1:
        fail("the run written whole came back as %d datasets" % len(whole))
    whole = whole[0]
    expected = {name: column(whole, name) for name in NAMES}
    seen, triangles, holders, border = set(), 0, set(), 0
    for data in fetch(split, time):
        triangles += data.GetNumberOfCells()
        ids = [int(i) for (i,) in column(data, "GlobalPointIds")]
        holders |= {int(r) for (r,) in column(data, "ProcessId")}
        values = {name: column(data, name) for name in NAMES}
        for i, point_id in enumerate(ids):
            if point_id in seen:
                border += 1
            seen.add(point_id)
            if data.GetPoint(i) != whole.GetPoint(point_id):
                fail("time %g: point %d lies at %s in its piece, %s written whole"
                     % (time, point_id, data.GetPoint(i), whole.GetPoint(point_id)))
            for name in NAMES:
                if values[name][i] != expected[name][point_id]:
                    fail("time %g: point %d has %s %s in its piece, %s written whole"
                         % (time, point_id, name, values[name][i], expected[name][point_id]))
    if triangles != whole.GetNumberOfCells():
        fail("time %g: the pieces hold %d triangles, the whole surface %d"
             % (time, triangles, whole.GetNumberOfCells()))
    if seen != set(range(whole.GetNumberOfPoints())):
        fail("time %g: the pieces hold %d of the %d points"
             % (time, len(seen), whole.GetNumberOfPoints()))
    if holders != set(range(min(ranks, pieces))):
        fail("the pieces were read by ranks %s, expected %d" % (sorted(holders), min(ranks, pieces)))
    if pieces > 1 and border == 0:
        fail("the pieces share no border point; the cut proves nothing")

print("PASS: %d pieces read by %d rank(s) hold the run written whole: %d points, %d triangles, "
      "%d border copies, at %d times" % (pieces, ranks, whole.GetNumberOfPoints(),
                                          whole.GetNumberOfCells(), border, 2))
