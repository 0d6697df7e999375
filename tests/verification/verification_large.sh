#!/usr/bin/env bash
# The verification suite's larger meshes, too slow for CI: the cantilever
# on 4, 8 and 16 cells through its depth (the last 245,760 tetrahedra),
# Cook's membrane on 16, 32 and 64 cells a side, NAFEMS LE10 on 73,728
# tetrahedra.
#   tests/verification/verification_large.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build}
"$build/tests/verification/verification_tests" --gtest_also_run_disabled_tests \
  --gtest_filter='*.DISABLED_*'
