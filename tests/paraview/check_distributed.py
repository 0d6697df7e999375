# The plugin's two filters under ParaView's distributed execution, run by
# `mpiexec -n RANKS pvbatch`: the same pipeline (TetSkin Bind Surface on the
# rest control mesh, then TetSkin Deform Surface over a run's control
# frames) on the surface
#   - read by one rank whole, the other ranks holding empty pieces, and
#   - split across the ranks by ParaView's RedistributeDataSet (each
#     triangle to one piece; a point on a border is in each piece beside it),
# both gathered on rank 0 and matched by point id. Every point of the split
# surface must be bound and moved as in the one-rank pipeline, in every
# piece that holds it. Its normal comes from the triangles around it in that
# piece: a point that only one piece holds has all of them there, so its
# normal must match too; a copy on a piece border has only some of them
# (ParaView 5.11 makes no ghost cells for surfaces), and must still be a
# unit normal on the same side.
# Usage: check_distributed.py PLUGIN RANKS SURFACE.vtp FRAMES_DIR
import glob
import sys

from paraview import servermanager
from paraview.simple import (ExtractSurface, GenerateIds, LoadPlugin, ProcessIdScalars,
                             RedistributeDataSet, XMLPolyDataReader,
                             XMLUnstructuredGridReader)
from pvcheck import fail

plugin, ranks, surface_file, frames_dir = sys.argv[1:5]
ranks = int(ranks)
partitions = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
if partitions != ranks:
    fail("pvbatch runs on %d ranks, expected %d (is it started by mpiexec?)" % (partitions, ranks))
LoadPlugin(plugin, remote=True, ns=globals())
if "TetSkinBindSurface" not in globals():
    fail("the plugin did not add TetSkinBindSurface")

control_files = sorted(glob.glob(frames_dir + "/control_*.vtu"))
if len(control_files) < 2:
    fail("expected a run's control frames in %s" % frames_dir)
control = XMLUnstructuredGridReader(FileName=control_files)
times = list(control.TimestepValues)
surface = GenerateIds(Input=XMLPolyDataReader(FileName=[surface_file]))
split = ExtractSurface(Input=RedistributeDataSet(Input=surface))


def pipeline(source):
    bind = TetSkinBindSurface(Input=source, ControlMesh=control)  # noqa: F821 (the plugin's)
    deform = TetSkinDeformSurface(Input=bind, ControlMesh=control)  # noqa: F821
    return ProcessIdScalars(Input=deform)


def fetch(proxy, time):
    proxy.UpdatePipeline(time)
    return servermanager.Fetch(proxy)


def table(data, name):
    array = data.GetPointData().GetArray(name)
    if array is None:
        fail("the gathered output lacks the point array %s (an empty piece without it?)" % name)
    return [array.GetTuple(i) for i in range(array.GetNumberOfTuples())]


NAMES = ("ControlIds", "Weights", "Normals")


def points_by_id(data):
    """Per point id: (rank, position, ControlIds, Weights, Normals) of each copy."""
    ids = table(data, "PointIds")
    rank = table(data, "ProcessId")
    position = [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]
    columns = [table(data, name) for name in NAMES]
    out = {}
    for i, (point_id,) in enumerate(ids):
        out.setdefault(int(point_id), []).append(
            (int(rank[i][0]), position[i]) + tuple(c[i] for c in columns))
    return out


def differ(a, b):
    return max(abs(x - y) for x, y in zip(a, b))


whole, distributed = pipeline(surface), pipeline(split)
for time in (times[0], times[-1]):
    one = points_by_id(fetch(whole, time))
    vertices = len(one)
    holders = {copy[0] for copies in one.values() for copy in copies}
    if holders != {0}:
        fail("the surface read whole should lie on rank 0 alone, lies on ranks %s" % sorted(holders))
    split_points = points_by_id(fetch(distributed, time))
    if set(split_points) != set(one):
        fail("time %g: the split surface has %d point ids, the whole one %d"
             % (time, len(split_points), vertices))
    holders = {copy[0] for copies in split_points.values() for copy in copies}
    if len(holders) != ranks:
        fail("the split surface lies on ranks %s, expected all %d" % (sorted(holders), ranks))
    size = max(max(abs(c) for c in copies[0][1]) for copies in one.values())
    border = exact_border = 0
    for point_id, copies in split_points.items():
        (_, position, ids, weights, normal), = one[point_id]
        for _, p, i, w, n in copies:
            if differ(p, position) > 1e-12 * size or i != ids or differ(w, weights) > 1e-12:
                fail("time %g: point %d is bound or moved otherwise on the split surface: %s, "
                     "whole %s" % (time, point_id, copies, one[point_id]))
            length = sum(c * c for c in n) ** 0.5
            same = differ(n, normal) <= 1e-9
            if len(copies) == 1 and not same:
                fail("time %g: point %d, held by one piece, has the normal %s, whole %s"
                     % (time, point_id, n, normal))
            if abs(length - 1) > 1e-9 or sum(a * b for a, b in zip(n, normal)) <= 0:
                fail("time %g: point %d's copy has the normal %s, whole %s"
                     % (time, point_id, n, normal))
            if len(copies) > 1:
                border += 1
                exact_border += same
    if border == 0:
        fail("the split made no border (%d ranks); the comparison would prove nothing" % ranks)

print("PASS: bound and deformed on %d ranks (the surface split, and read by one rank with "
      "empty pieces on the others) as on one rank: %d vertices at %d times; %d copies on piece "
      "borders, %d of them with the one-rank normal" % (ranks, vertices, 2, border, exact_border))
