#!/usr/bin/env bash
# SPDX-License-Identifier: AGPL-3.0-or-later
# Issue #71's benchmark: three bunnies (finest level, 64k skins) dropped into
# a bowl of about 100k triangles (make_bowl.py as contact_bench.sh makes it,
# placed 2.5 times larger) and onto each other; bodies_bench's table.
#
# usage: tests/bench/bodies_bench.sh [BUILD_DIR] [STEPS] [SETTLE] [SKIN_STIFFNESS]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:-$root/build}
steps=${2:-20}
settle=${3:-40}
stiffness=${4:-0}  # N/m per skin vertex; 0: automatic
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$root/data/tools/make_bowl.py" "$work/bowl_100k.obj" 9 0.6 75 100 250
"$build/tests/bench/bodies_bench" "$work/bowl_100k.obj" "$steps" "$settle" "$stiffness"
