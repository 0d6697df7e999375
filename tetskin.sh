#!/usr/bin/env bash
# TetSkin's one entry point on a Debian bookworm machine.
#   ./tetskin.sh demo   install what is missing, build, run the main job on the bundled bunny
#   ./tetskin.sh test   install what is missing, build, run the whole test suite
#   ./tetskin.sh build  install what is missing and build (Release, in build/), the
#                       ParaView plugin included
#   ./tetskin.sh deps   only install the Debian packages
# Environment: BUILD_DIR (default build), JOBS (default: all cores),
# FUZZ_SECONDS (test: each reader's fuzzer runs this long, default 30).
set -euo pipefail
cd "$(dirname "$0")"
ROOT=$PWD
BUILD_DIR=${BUILD_DIR:-build}
# Compiler cache keyed on paths relative to the checkout: clones elsewhere hit it too.
export CCACHE_BASEDIR="$ROOT"
JOBS=${JOBS:-$(nproc)}

# (python3-matplotlib: the verification suite's convergence plot;
# libsuitesparse-dev, libhypre-dev: solver_bench's baselines, CHOLMOD and
# BoomerAMG; libopenblas0-pthread: the BLAS CHOLMOD's factorization runs on;
# clang, libclang-rt-14-dev: the readers' fuzzers, libFuzzer; mpi-default-bin:
# mpiexec, for the ParaView filters under pvbatch on several ranks.)
DEPS=(
  cmake ninja-build g++ pkg-config ccache dpkg-dev
  libeigen3-dev nlohmann-json3-dev libcli11-dev libtbb-dev
  libvtk9-qt-dev qtbase5-dev libglew-dev libpng-dev zlib1g-dev liblz4-dev liblzma-dev
  libtet1.5-dev libnglib-dev libcgal-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth assimp-testmodels netgen-doc paraview mpi-default-bin
  paraview-dev qtxmlpatterns5-dev-tools
  pybind11-dev python3-dev python3-numpy python3-pytest python3-vtk9 python3-matplotlib
  libsuitesparse-dev libhypre-dev libopenblas0-pthread
  clang libclang-rt-14-dev
)

log() { printf '\n==> %s\n' "$*" >&2; }

# stage NAME COMMAND...: runs COMMAND and keeps its wall time; the times are
# printed when the script ends (print_stage_times), failed or not, so that
# every CI log shows where its minutes went. (COMMAND runs as a plain
# statement: in an `||` list, set -e would be off inside it.)
STAGE_TIMES=() STAGE_NOW="" STAGE_START=0
minutes() { awk -v s="$1" 'BEGIN { printf "%.1f", s / 60 }'; }
stage() {
  STAGE_NOW=$1 STAGE_START=$SECONDS
  shift
  "$@"
  STAGE_TIMES+=("$(printf '%-26s %5s min' "$STAGE_NOW" "$(minutes $((SECONDS - STAGE_START)))")")
  STAGE_NOW=""
}
print_stage_times() {
  [ -n "$STAGE_NOW" ] &&
    STAGE_TIMES+=("$(printf '%-26s %5s min  (failed)' "$STAGE_NOW" "$(minutes $((SECONDS - STAGE_START)))")")
  [ ${#STAGE_TIMES[@]} -eq 0 ] && return 0
  printf '\n==> stage times (%s min in all)\n' "$(minutes $SECONDS)" >&2
  printf '    %s\n' "${STAGE_TIMES[@]}" >&2
}
trap print_stage_times EXIT

install_deps() {
  local missing=()
  for p in "${DEPS[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  log "installing ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# configure DIR [cmake args...]
configure() {
  local dir=$1
  shift
  cmake -S "$ROOT" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTETSKIN_WERROR=ON \
    -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache "$@" >/dev/null
}

# build [cmake args...]
build() {
  install_deps
  log "building in $BUILD_DIR"
  configure "$BUILD_DIR" "$@"
  cmake --build "$BUILD_DIR" -j "$JOBS"
}

# ParaView's Python packages conflict with the VTK development packages, so
# they are unpacked into the build folder, never installed
# (doc/dev/platform-notes.md); the tests run Debian's pvpython with them, and
# the ParaView plugin's build reads ParaView's class hierarchies from them.
paraview_python() {
  local root=$ROOT/$BUILD_DIR/paraview-python
  if [ ! -x "$root/usr/bin/pvpython" ]; then
    log "unpacking python3-paraview into $root"
    local tmp
    tmp=$(mktemp -d)
    (cd "$tmp" && { apt-get download python3-paraview >/dev/null 2>&1 ||
      { apt-get update -qq && apt-get download python3-paraview >/dev/null; }; })
    mkdir -p "$root"
    dpkg -x "$tmp"/python3-paraview_*.deb "$root"
    rm -rf "$tmp"
  fi
  echo "$root"
}

# Everything that needs an X display (rendering, GUI) runs under Xvfb when
# there is no display of our own. -noreset: by default an X server resets when
# its last client leaves and refuses connections meanwhile, which made a test
# starting just as another ended fail now and then ("bad X server connection").
with_display() {
  if [ -n "${DISPLAY:-}" ]; then "$@"; else xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"; fi
}

demo() {
  build
  local tetskin=$BUILD_DIR/app/cli/tetskin out=out/demo
  mkdir -p "$out"
  log "the bundled surfaces"
  "$tetskin" info data/bunny.obj data/bunny_8k.obj data/bunny_64k.obj
  log "model generation: bunny -> multi-level tetrahedral dataset"
  "$tetskin" build data/bunny.obj --decimate --levels 3 --min-elements 600 \
    --max-elements 12000 -o "$out/bunny"
  "$tetskin" info "$out/bunny.json"
  log "binding the 64k-triangle bunny to the finest level"
  "$tetskin" bind "$out/bunny.json" data/bunny_64k.obj -o "$out/bunny_64k_binding.vtp"
  log "deforming it with a rotated control mesh (bound surfaces follow rigid motion exactly)"
  awk 'NR <= 2 || /^#/ { print; next }
       { c = cos(0.5); s = sin(0.5); printf "%s %.17g %.17g %.17g\n", $1, c*$2 - s*$3, s*$2 + c*$3, $4 }' \
    "$out/bunny.node" >"$out/bunny_rotated.node"
  "$tetskin" deform "$out/bunny.json" "$out/bunny_64k_binding.vtp" \
    --positions "$out/bunny_rotated.node" -o "$out/bunny_64k_rotated.vtp"
  log "simulating the finest level (wobble), the 64k bunny following it"
  "$tetskin" simulate "$out/bunny.json" --scenario wobble --steps 60 --every 2 \
    --surface data/bunny_64k.obj -o "$out/wobble.pvd" --log "$out/wobble_steps.csv"
  log "dropping it onto the floor, and filming the drop (the floor drawn under it)"
  "$tetskin" simulate "$out/bunny.json" --scenario drop --steps 60 --every 2 -o "$out/drop.pvd" -q
  with_display "$tetskin" render "$out/bunny.json" --run "$out/drop.pvd" --size 640x480 \
    -o "$out/drop.ogv"
  log "rendering 30 animated frames on each render path"
  for path in cpu gpu-1pass gpu-2pass; do
    with_display "$tetskin" render "$out/bunny.json" --surface data/bunny_64k.obj --path "$path" \
      --frames 30 --control wireframe --level 0 -o "$out/bunny_$path.png"
  done
  log "rendering 30 animated frames with fur (textured 8k bunny, both fur paths)"
  for path in fur-cpu fur-gpu; do
    with_display "$tetskin" render "$out/bunny.json" --surface data/bunny_8k_tex.obj \
      --texture data/bunny_texture.png --path "$path" --frames 30 --level 0 -o "$out/bunny_$path.png"
  done
  log "filming the recorded wobble run with fur (render --run: one image per frame, and a movie)"
  with_display "$tetskin" render "$out/bunny.json" --run "$out/wobble.pvd" \
    --surface data/bunny_8k_tex.obj --texture data/bunny_texture.png --path fur-gpu \
    --size 640x480 -o "$out/film/wobble.png"
  with_display "$tetskin" render "$out/bunny.json" --run "$out/wobble.pvd" \
    --surface data/bunny_8k_tex.obj --texture data/bunny_texture.png --path fur-gpu \
    --size 640x480 -o "$out/wobble.ogv"
  log "export for ParaView"
  "$tetskin" convert data/bunny_64k.obj "$out/bunny_64k.vtp"
  for level in 0 1 2; do "$tetskin" convert "$out/bunny.json" "$out/bunny_level$level.vtu" --level $level; done
  log "demo outputs are in $out/ (open them in ParaView)"
}

sanitized_tests() {
  # The readers face hostile input, and the simulation's kernels (vector
  # code in two instruction sets) may rely on what only optimization hides:
  # their tests run in a Debug build under ASan + UBSan, with LeakSanitizer
  # on (tests/sanitizers/lsan.supp names the third-party leaks it forgives).
  # What this stage proves is the readers' and the kernels' memory safety,
  # so it runs their suites and the fuzz corpus, not the command line's:
  # those run whole pipelines (TetGen, CGAL, VTK's rendering) that the
  # Release suite runs, and under ASan they took half of CI's time (the
  # cold run in doc/dev/testing.md).
  log "IO and simulation kernel tests under AddressSanitizer + UndefinedBehaviorSanitizer + LeakSanitizer (Debug)"
  local dir=${BUILD_DIR}-asan
  configure "$dir" -DCMAKE_BUILD_TYPE=Debug -DTETSKIN_SANITIZE=ON -DTETSKIN_BUILD_GUI=OFF \
    -DTETSKIN_BUILD_BENCHMARKS=OFF
  export LSAN_OPTIONS="suppressions=$ROOT/tests/sanitizers/lsan.supp print_suppressions=0"
  cmake --build "$dir" -j "$JOBS" --target core_tests io_tests vtkio_tests \
    simulation_kernel_tests session_tests fuzz_corpus_tests
  (cd "$dir" && ctest -j "$JOBS" -L "^(core|io|vtkio|simulation-kernels|session)$" \
    -LE rendering --output-on-failure --no-tests=error)
  unset LSAN_OPTIONS
}

thread_tests() {
  # The threaded parts under ThreadSanitizer: a run stepped on its own thread
  # while another reads, pulls, records and rebinds (SimulationRunner, the
  # GUI's), and the parallel loops of the simulation, binding and
  # deformation, which run on std::threads in this build (core/Parallel.h).
  # A race fails the test that ran into it. VTK's own parallel loops run on
  # TBB, which TSan cannot see into: they run sequentially here. (-O1 -g1:
  # enough for TSan and its stacks, and a third quicker to compile than
  # RelWithDebInfo's -O2 -g; GridHierarchy's tests, of serial code and the
  # slowest under TSan, are left out, and so is boundary_faces_tests, which
  # alone would build the meshing module and CGAL here.)
  log "threaded tests under ThreadSanitizer"
  local dir=${BUILD_DIR}-tsan
  configure "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DTETSKIN_TSAN=ON -DTETSKIN_BUILD_GUI=OFF -DTETSKIN_BUILD_BENCHMARKS=OFF \
    -DTETSKIN_BUILD_PYTHON=OFF -DTETSKIN_BUILD_PARAVIEW_PLUGIN=OFF
  export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$ROOT/tests/sanitizers/tsan.supp"
  export VTK_SMP_BACKEND_IN_USE=Sequential
  cmake --build "$dir" -j "$JOBS" --target session_tests simulation_kernel_tests binding_tests \
    deformation_tests
  (cd "$dir" && ctest -j "$JOBS" -L "^(session|simulation-kernels|binding|deformation)$" \
    -E "^GridHierarchy\." --output-on-failure --no-tests=error)
  unset TSAN_OPTIONS VTK_SMP_BACKEND_IN_USE
}

fuzz_tests() {
  # Every reader's libFuzzer target for FUZZ_SECONDS on the committed corpus
  # (tests/fuzz; its seeds and regressions also run in every build's suite).
  log "the readers' fuzzers (libFuzzer, ASan + UBSan), ${FUZZ_SECONDS:-30} s each"
  local dir=${BUILD_DIR}-fuzz
  CC=clang CXX=clang++ configure "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTETSKIN_FUZZ=ON \
    -DTETSKIN_BUILD_GUI=OFF -DTETSKIN_BUILD_BENCHMARKS=OFF -DTETSKIN_BUILD_PYTHON=OFF \
    -DTETSKIN_BUILD_PARAVIEW_PLUGIN=OFF
  cmake --build "$dir" -j "$JOBS" --target fuzzers
  tests/fuzz/run_fuzzers.sh "$dir" "${FUZZ_SECONDS:-30}"
}

# The build with the ParaView plugin and tests: ParaView's Python packages
# are unpacked (they need the installed packages first) into the build folder.
build_with_paraview() {
  install_deps
  mkdir -p "$BUILD_DIR"
  build -DTETSKIN_PARAVIEW_ROOT="$(paraview_python)"
}

whole_suite() {
  log "the whole test suite"
  # --repeat until-pass:3: a test that fails is run again, up to 3 times in all
  # (a real failure fails all three times).
  (cd "$BUILD_DIR" && with_display ctest -j "$JOBS" --output-on-failure --no-tests=error \
    --repeat until-pass:3)
}

run_tests() {
  stage "packages" install_deps
  stage "build" build_with_paraview
  stage "sanitized tests (ASan)" sanitized_tests
  stage "threaded tests (TSan)" thread_tests
  stage "fuzzers" fuzz_tests
  stage "whole suite" whole_suite
}

case "${1:-}" in
  deps) install_deps ;;
  build) build_with_paraview ;;
  demo) demo ;;
  test) run_tests ;;
  *)
    sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'
    exit 2
    ;;
esac
