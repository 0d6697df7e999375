#!/usr/bin/env bash
# Issue #54's benchmark: deforming a surface of at least 10M triangles (the
# bundled 64k bunny, Loop-subdivided 4 times: 16.4M triangles) per frame in
# ParaView's distributed server, on 1 rank and on 2 in the same run, with
# memory per rank. Steps, all timed apart from the benchmark itself:
#   1. the surface: data/bunny_64k.obj Loop-subdivided (pvpython, VTK's filter);
#   2. its binding to the bunny's finest level (tetskin bind);
#   3. a simulated run of that level (tetskin simulate: the control frames);
#   4. the binding deformed to frame 0, written in 2 pieces
#      (tetskin deform --pieces 2: the .pvtp each rank reads its piece of);
#   5. distributed_deform.py under pvbatch --symmetric on 1 rank, then under
#      mpiexec -n 2 (Open MPI binds each rank to its own core).
# Usage: tests/bench/distributed_deform.sh [BUILD_DIR] [SUBDIVISIONS] [WORK_DIR]
# (needs the build with the ParaView plugin: ./tetskin.sh build)
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=$(realpath "${1:-build}")
SUBDIVISIONS=${2:-4}
WORK=${3:-$(mktemp -d)}
mkdir -p "$WORK"
PV_ROOT=$BUILD/paraview-python
PLUGIN=$(find "$BUILD" -name 'TetSkinFilters.so' | head -n 1)
[ -n "$PLUGIN" ] || { echo "no TetSkinFilters.so in $BUILD (./tetskin.sh build)" >&2; exit 1; }
TETSKIN=$BUILD/app/cli/tetskin
LEVEL=2
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
seconds() { local start=$1; echo "$(( $(date +%s%N) / 1000000 - start ))"; }
now() { echo $(( $(date +%s%N) / 1000000 )); }

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(free -g | awk '/Mem:/ {print $2}') GB"
echo "commit: $(git rev-parse --short HEAD)$(git diff --quiet || echo ' (with uncommitted changes)'), $(date -u +%F)"

t=$(now)
cat > "$WORK/subdivide.py" <<PY
from vtkmodules.vtkFiltersModeling import vtkLoopSubdivisionFilter
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
from vtkmodules.vtkFiltersCore import vtkCleanPolyData
reader = vtkOBJReader(); reader.SetFileName("data/bunny_64k.obj")
clean = vtkCleanPolyData(); clean.SetInputConnection(reader.GetOutputPort())
loop = vtkLoopSubdivisionFilter(); loop.SetInputConnection(clean.GetOutputPort())
loop.SetNumberOfSubdivisions($SUBDIVISIONS)
writer = vtkXMLPolyDataWriter(); writer.SetInputConnection(loop.GetOutputPort())
writer.SetFileName("$WORK/surface.vtp"); writer.SetDataModeToAppended(); writer.Write()
PY
if [ -f "$WORK/surface.vtp" ]; then  # (a WORK_DIR given again: reused)
  echo "1. the subdivided surface of an earlier run reused"
else
  "$PV_ROOT/usr/bin/pvpython" tests/paraview/pvwrapper.py "$PV_ROOT" "$WORK/subdivide.py"
  echo "1. subdivided bunny_64k $SUBDIVISIONS times: $(seconds "$t") ms"
fi
python3 -c "import re, sys; head = open(sys.argv[1], 'rb').read(4096).decode('latin-1')
print('   %s vertices, %s triangles' % tuple(re.search(r'Number%s=\"(\d+)\"' % k, head).group(1)
                                         for k in ('OfPoints', 'OfPolys')))" "$WORK/surface.vtp"

if [ -f "$WORK/pieces.pvtp" ]; then  # (a WORK_DIR given again: its inputs reused)
  echo "2-4. the binding, run and pieces of an earlier run reused"
else
t=$(now)
"$TETSKIN" bind data/bunny.json "$WORK/surface.vtp" --level $LEVEL -o "$WORK/bound.vtp" | tail -n 1
echo "2. bound to level $LEVEL: $(seconds "$t") ms (the command: read, bind, write)"

t=$(now)
"$TETSKIN" simulate data/bunny.json --level $LEVEL --steps 10 --every 2 -q -o "$WORK/run.pvd" >/dev/null
echo "3. simulated level $LEVEL, 6 frames: $(seconds "$t") ms"

t=$(now)
"$TETSKIN" deform data/bunny.json "$WORK/bound.vtp" --positions "$WORK/run_frames/control_00000.vtu" \
  --pieces 2 -o "$WORK/pieces.pvtp" >/dev/null
echo "4. written in 2 pieces: $(seconds "$t") ms ($(du -ch "$WORK"/pieces_piece*.vtp | tail -n1 | cut -f1))"
fi

FIRST_NODE=$(python3 -c "import json; print(json.load(open('data/bunny.json'))['levels'][$LEVEL]['nodes'][0])")
# 1 rank on one core (Open MPI binds a rank to a core), 1 rank on every
# core (its deformation threaded), 2 ranks on a core each.
for run in "1 --bind-to core" "1 --bind-to none" "2 --bind-to core"; do
  set -- $run
  echo "5. $1 rank(s), $2 $3:"
  mpiexec -n "$1" "$2" "$3" pvbatch --symmetric tests/paraview/pvwrapper.py "$PV_ROOT" \
    tests/bench/distributed_deform.py "$PLUGIN" "$WORK/pieces.pvtp" "$WORK/run_frames" "$FIRST_NODE" |
    grep '^rank' | sort
done
echo "(work files in $WORK)"
