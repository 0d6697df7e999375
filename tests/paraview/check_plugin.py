# Loads TetSkin's ParaView plugin into pvpython and runs its two filters as a
# ParaView user would, against what the command line wrote for the same run:
# TetSkin Bind Surface on the rest control mesh gives the binding `tetskin
# bind` wrote, and TetSkin Deform Surface on every control frame of a
# `tetskin simulate --surface` run gives that run's own surface frames.
# Usage: check_plugin.py PLUGIN DATASET.json LEVEL BOUND.vtp FRAMES_DIR FRAMES
import glob
import json
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, XMLPolyDataReader, XMLUnstructuredGridReader
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


plugin, dataset, level, bound_file, frames_dir, frames = sys.argv[1:7]
level, frames = int(level), int(frames)
LoadPlugin(plugin, remote=False, ns=globals())
for name in ("TetSkinBindSurface", "TetSkinDeformSurface"):
    if name not in globals():
        fail("the plugin did not add %s" % name)

with open(dataset) as f:
    first_node = json.load(f)["levels"][level]["nodes"][0]

control_files = sorted(glob.glob(frames_dir + "/control_*.vtu"))
surface_files = sorted(glob.glob(frames_dir + "/surface_*.vtp"))
if len(control_files) != frames or len(surface_files) != frames:
    fail("expected %d control and surface frames, found %d and %d"
         % (frames, len(control_files), len(surface_files)))

bound = XMLPolyDataReader(FileName=[bound_file])
control = XMLUnstructuredGridReader(FileName=control_files)
written = XMLPolyDataReader(FileName=surface_files)
times = list(control.TimestepValues)


def fetch(proxy, time):
    proxy.UpdatePipeline(time)
    return servermanager.Fetch(proxy)


def rows(array):
    return [array.GetTuple(i) for i in range(array.GetNumberOfTuples())]


def largest_difference(a, b):
    return max(abs(x - y) for ra, rb in zip(a, b) for x, y in zip(ra, rb))


bound_data = fetch(bound, times[0])
vertices = bound_data.GetNumberOfPoints()
bounds = bound_data.GetBounds()
size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])

# Binding: frame 0 is the rest state; its ids are the level's own, the
# command line's the dataset's (first_node more).
bind = TetSkinBindSurface(Input=bound, ControlMesh=control)
made = fetch(bind, times[0])
if made.GetNumberOfPoints() != vertices:
    fail("TetSkin Bind Surface gave %d points, expected %d" % (made.GetNumberOfPoints(), vertices))
made_ids = rows(made.GetPointData().GetArray("ControlIds"))
file_ids = rows(bound_data.GetPointData().GetArray("ControlIds"))
shifted = [tuple(i - first_node for i in r) for r in file_ids]
if made_ids != shifted:
    fail("TetSkin Bind Surface chose other triangles than tetskin bind")
weights = largest_difference(rows(made.GetPointData().GetArray("Weights")),
                             rows(bound_data.GetPointData().GetArray("Weights")))
if weights > 1e-12:
    fail("TetSkin Bind Surface's weights differ from tetskin bind's by %g" % weights)


@calldata_type(VTK_STRING)
def keep_error(caller, event, message):
    errors.append(message)


# Deformation: without the level's offset the ids run past the frame's
# points. The filter's error (and its executive's) is caught, checked and
# kept off the log, where it would read as a failure.
deform = TetSkinDeformSurface(Input=bound, ControlMesh=control)
errors = []
algorithm = deform.GetClientSideObject()
observers = [(o, o.AddObserver("ErrorEvent", keep_error))
             for o in (algorithm, algorithm.GetExecutive())]
if fetch(deform, times[0]).GetNumberOfPoints() != 0:
    fail("ControlIdOffset 0 should be an error (empty output)")
for o, tag in observers:
    o.RemoveObserver(tag)
if not any("ControlIdOffset 0" in e and "outside the dataset" in e for e in errors):
    fail("ControlIdOffset 0: expected an error naming the offset and the node, got %r" % errors)
deform.ControlIdOffset = first_node
moved = 0.0
for time in times:
    out = fetch(deform, time)
    reference = fetch(written, time)
    if out.GetNumberOfPoints() != vertices:
        fail("time %g: %d points, expected %d" % (time, out.GetNumberOfPoints(), vertices))
    points = rows(out.GetPoints().GetData())
    position = largest_difference(points, rows(reference.GetPoints().GetData()))
    normal = largest_difference(rows(out.GetPointData().GetArray("Normals")),
                                rows(reference.GetPointData().GetArray("Normals")))
    if position > 1e-9 * size or normal > 1e-9:
        fail("time %g: positions differ by %g, normals by %g from the run's surface"
             % (time, position, normal))
    moved = max(moved, largest_difference(points, rows(bound_data.GetPoints().GetData())))
if not moved > 1e-3 * size:
    fail("the surface never moved (%g); the comparison would prove nothing" % moved)

print("PASS: both filters from the plugin; %d frames of %d vertices as the command line "
      "wrote them (largest motion %.3g of a %.3g body)" % (len(times), vertices, moved, size))
