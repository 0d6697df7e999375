#!/usr/bin/env bash
# SPDX-License-Identifier: AGPL-3.0-or-later
# Issue #70's contact benchmark: makes a bowl of about 100k triangles with
# data/tools/make_bowl.py (inner radius 9, 0.6 thick, 75 degrees, 100 rings
# of 250 segments) and runs contact_bench on it (the bunny's finest level,
# its 64k skin resting in the bowl). Prints contact_bench's table.
#
# usage: tests/bench/contact_bench.sh [BUILD_DIR] [STEPS] [multigrid]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:-$root/build}
steps=${2:-20}
solver=${3:-cg}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$root/data/tools/make_bowl.py" "$work/bowl_100k.obj" 9 0.6 75 100 250
"$build/tests/bench/contact_bench" "$work/bowl_100k.obj" "$steps" "$solver"
