# Runs a script under Debian's pvpython with ParaView's own Python packages
# (unpacked from python3-paraview into a build-local folder, see
# doc/dev/platform-notes.md) instead of the system VTK modules, which would
# make pvpython crash. Usage: pvpython pvwrapper.py ROOT SCRIPT ARGS...
import os
import runpy
import sys

root = sys.argv[1]
sys.path = [p for p in sys.path if "dist-packages" not in p]
sys.path.insert(0, root + "/usr/lib/python3/dist-packages")
script = sys.argv[2]
sys.path.insert(0, os.path.dirname(os.path.abspath(script)))  # (its shared pvcheck.py)
sys.argv = sys.argv[2:]
runpy.run_path(script, run_name="__main__")
