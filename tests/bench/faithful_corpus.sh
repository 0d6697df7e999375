#!/usr/bin/env bash
# Issue #68's corpus: `tetskin build IN --decimate -q` on every surface of a
# corpus (the test data's broken surfaces, Debian's assimp, Netgen and
# OpenCASCADE sample models: scans, open and holed surfaces, several parts,
# CAD), with the demo's targets and with --levels 2 --min-elements 800
# --max-elements 6000. Prints one markdown row per input and targets: each
# level's elements and input -> level distance (mean % / max % of the
# input's diagonal, build's own table), or build's first error line; and
# the wall time. Inputs that are not installed are skipped.
# Usage: tests/bench/faithful_corpus.sh [BUILD_DIR] [INPUT...]
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=$(realpath "${1:-build}")
shift || true
TETSKIN=$BUILD/app/cli/tetskin
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

if [ $# -gt 0 ]; then
  INPUTS=("$@")
else
  INPUTS=(
    data/bunny.obj
    tests/data/bunny_holed.obj tests/data/open_sheet.obj tests/data/overlapping_spheres.obj
    tests/data/soup_with_gaps.obj tests/data/nonmanifold_fins.obj tests/data/inverted_part.obj
    /usr/share/assimp/models/STL/Wuson.stl /usr/share/assimp/models/STL/sphereWithHole.stl
    /usr/share/assimp/models/OBJ/spider.obj /usr/share/assimp/models/OBJ/regr01.obj
    /usr/share/assimp/models/PLY/pond.0.ply
    /usr/share/doc/netgen/examples/part1.stl /usr/share/doc/netgen/examples/hinge.stl
    /usr/share/opencascade/data/stl/shape.stl /usr/share/opencascade/data/stl/sh1.stl
    /usr/share/opencascade/data/stl/propeller.stl /usr/share/opencascade/data/stl/video_part.stl
    /usr/share/opencascade/data/stl/head.stl /usr/share/opencascade/data/stl/motor.stl
    /usr/share/opencascade/data/stl/TR12J_OCC.stl /usr/share/opencascade/data/stl/bearing.stl
  )
fi

echo "| input | targets | levels: elements (mean % / max %) | s |"
echo "|---|---|---|---|"
for input in "${INPUTS[@]}"; do
  [ -f "$input" ] || { echo "skipped $input: not installed" >&2; continue; }
  for targets in demo 800/6000; do
    if [ "$targets" = demo ]; then args=(); else
      args=(--levels 2 --min-elements 800 --max-elements 6000); fi
    log=$OUT/log
    start=$(date +%s.%N)
    status=0
    "$TETSKIN" build "$input" --decimate -q "${args[@]}" -o "$OUT/d" >"$log" 2>&1 || status=$?
    seconds=$(echo "$(date +%s.%N) - $start" | bc)
    if [ $status -eq 0 ]; then
      # build's table: level elements nodes mesher quality min-dih max-r/e mean% max% input
      levels=$(awk '/^level +elements/ {t=1; next} t && /^[0-9]+ / {
                 printf "%s%s (%s/%s)", sep, $2, $8, $9; sep=", " } t && !/^[0-9]+ / {t=0}' "$log")
    else
      levels="refused: $(grep -m1 -i 'error' "$log" | cut -c1-160)"
    fi
    printf '| `%s` | %s | %s | %.1f |\n' "$(basename "$input")" "$targets" "$levels" "$seconds"
  done
done
