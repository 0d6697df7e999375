# The distributed recipe of doc/user/paraview.md, run as the page shows it:
# its "<!-- example: pvbatch -->" script under `mpiexec -n RANKS pvbatch`
# in a fresh folder holding scan.vtp and run_frames/, then its output read
# back whole here: a .pvtp per control frame with a piece per rank, every
# vertex of the surface in them (border vertices in each piece beside the
# border) with the filters' arrays, and a .pvd that lists them.
# Usage: check_recipe.py PAGE PLUGIN RANKS SURFACE.vtp FRAMES_DIR MPIEXEC PVBATCH WRAPPER ROOT
import glob
import os
import re
import subprocess
import sys
import tempfile

from paraview import servermanager
from paraview.simple import PVDReader, XMLPolyDataReader
from pvcheck import fail

page, plugin, ranks, surface, frames_dir, mpiexec, pvbatch, wrapper, root = sys.argv[1:10]
ranks = int(ranks)
found = re.findall(r"<!-- example: pvbatch -->\n```python\n(.*?)```", open(page).read(), re.S)
if len(found) != 1:
    fail("%s has %d pvbatch examples, expected 1" % (page, len(found)))
control_frames = len(glob.glob(frames_dir + "/control_*.vtu"))

with tempfile.TemporaryDirectory() as folder:
    os.symlink(surface, os.path.join(folder, "scan.vtp"))
    os.symlink(frames_dir, os.path.join(folder, "run_frames"))
    with open(os.path.join(folder, "bind_deform.py"), "w") as script:
        script.write(found[0])
    # (Without the MPI variables of this pvpython, a singleton MPI process:
    # mpiexec would take itself for a child of it.)
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("OMPI_", "PMIX_", "OPAL_", "PRTE_"))}
    env.update(TETSKIN_PLUGIN=plugin, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    done = subprocess.run([mpiexec, "--oversubscribe", "-n", str(ranks), pvbatch, wrapper, root,
                           "bind_deform.py"], cwd=folder, env=env, capture_output=True,
                          text=True, timeout=150)
    if done.returncode != 0:
        fail("the recipe failed (%d): %s" % (done.returncode, (done.stdout + done.stderr)[-3000:]))
    written = sorted(glob.glob(folder + "/deformed/frame_*.pvtp"))
    if len(written) != control_frames:
        fail("the recipe wrote %d frames for %d control frames" % (len(written), control_frames))
    pieces = sorted(glob.glob(folder + "/deformed/frame_0000/*.vtp")) or \
        sorted(glob.glob(folder + "/deformed/frame_0000_*.vtp"))
    if len(pieces) != ranks:
        fail("frame 0 has %d pieces, expected one per rank (%d)" % (len(pieces), ranks))
    rest = servermanager.Fetch(XMLPolyDataReader(FileName=[surface]))
    series = PVDReader(FileName=os.path.join(folder, "deformed.pvd"))
    times = list(series.TimestepValues)
    if len(times) != control_frames:
        fail("deformed.pvd lists %d times, expected %d" % (len(times), control_frames))
    for time in (times[0], times[-1]):
        series.UpdatePipeline(time)
        data = servermanager.Fetch(series)
        if data.GetNumberOfCells() != rest.GetNumberOfCells():
            fail("time %g: %d triangles read back, the surface has %d"
                 % (time, data.GetNumberOfCells(), rest.GetNumberOfCells()))
        if data.GetNumberOfPoints() < rest.GetNumberOfPoints():
            fail("time %g: %d points read back, the surface has %d"
                 % (time, data.GetNumberOfPoints(), rest.GetNumberOfPoints()))
        for name in ("ControlIds", "Weights", "Normals", "Displacement"):
            if data.GetPointData().GetArray(name) is None:
                fail("time %g: the frames read back lack the array %s" % (time, name))

print("PASS: the page's pvbatch recipe on %d ranks wrote %d frames of %d pieces, read back whole "
      "(%d triangles)" % (ranks, len(written), len(pieces), rest.GetNumberOfCells()))
