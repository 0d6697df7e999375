# The TetSkin Deform Surface filter on a large surface in pieces, per frame,
# on each rank of `pvbatch --symmetric` (one rank, or `mpiexec -n N`): each
# rank reads its own pieces of a .pvtp (a binding, as `tetskin deform
# --pieces` writes one) and the whole control frame, deforms its piece for
# every frame of a run, and prints one line: its vertices, the median and
# range of its deform time per frame (the filter's update alone: the control
# frame read is timed apart), and its memory (VmRSS before the surface is
# read, VmHWM at the end). Driven by tests/bench/distributed_deform.sh.
# Usage: pvbatch --symmetric distributed_deform.py PLUGIN SURFACE.pvtp FRAMES_DIR FIRST_NODE
import glob
import os
import statistics
import sys
import time

from paraview import servermanager
from paraview.simple import (LoadPlugin, XMLPartitionedPolydataReader,
                             XMLUnstructuredGridReader)


def memory_mb(field):
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith(field + ":"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


plugin, surface_file, frames_dir, first_node = sys.argv[1:5]
module = servermanager.vtkProcessModule.GetProcessModule()
rank, ranks = module.GetPartitionId(), module.GetNumberOfLocalPartitions()
controller = module.GetGlobalController()
LoadPlugin(plugin, ns=globals())
baseline = memory_mb("VmRSS")

control = XMLUnstructuredGridReader(FileName=sorted(glob.glob(frames_dir + "/control_*.vtu")))
times = list(control.TimestepValues)
surface = XMLPartitionedPolydataReader(FileName=[surface_file])
surface.UpdatePipeline()
vertices = surface.GetClientSideObject().GetOutputDataObject(0).GetNumberOfPoints()  # its piece
deform = TetSkinDeformSurface(Input=surface, ControlMesh=control)  # noqa: F821 (the plugin's)
deform.ControlIdOffset = int(first_node)

deform_ms, read_ms = [], []
for i, t in enumerate(times * 2):  # every frame twice: the first pass warms up
    controller.Barrier()
    start = time.perf_counter()
    control.UpdatePipeline(t)
    read = time.perf_counter()
    deform.UpdatePipeline(t)
    done = time.perf_counter()
    if i >= len(times):
        read_ms.append(1e3 * (read - start))
        deform_ms.append(1e3 * (done - read))
controller.Barrier()
print("rank %d of %d (%d cores): %d vertices, deform %.1f ms per frame (%.1f .. %.1f, %d frames), "
      "control frame read %.1f ms, memory %.0f MB before the surface, peak %.0f MB; frames %s"
      % (rank, ranks, len(os.sched_getaffinity(0)), vertices, statistics.median(deform_ms),
         min(deform_ms), max(deform_ms), len(deform_ms), statistics.median(read_ms), baseline,
         memory_mb("VmHWM"), " ".join("%.0f" % ms for ms in deform_ms)), flush=True)
